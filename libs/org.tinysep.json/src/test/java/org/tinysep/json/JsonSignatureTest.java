package org.tinysep.json;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class JsonSignatureTest {

    private static final byte[] KEY = "0123456789abcdef0123".getBytes(StandardCharsets.UTF_8);
    private static final String TOPIC = "tinysep/flat-7/alert/3";

    @Test
    void aSignedObjectChecksOnItsTopicAndGivesBackTheUnsignedText() {
        String json = "{\"id\":\"3\",\"state\":\"OPEN\"}";
        String signed = JsonSignature.sign(KEY, TOPIC, json);
        assertTrue(signed.startsWith("{\"id\":\"3\",\"state\":\"OPEN\",\"sig\":\""), signed);
        JsonSignature.Checked c = JsonSignature.check(KEY, TOPIC, signed);
        assertTrue(c.signed() && c.valid(), signed);
        assertEquals(json, c.unsigned());
        assertEquals("{\"sig\":\"" + JsonSignature.mac(KEY, TOPIC, "{}") + "\"}", JsonSignature.sign(KEY, TOPIC, "{}"));
    }

    @Test
    void anotherTopicKeyOrTextIsNotValidAndUnsignedTextIsSaidSo() {
        String signed = JsonSignature.sign(KEY, TOPIC, "{\"state\":\"OPEN\"}");
        assertFalse(JsonSignature.check(KEY, "tinysep/flat-8/alert/3", signed).valid());
        assertFalse(JsonSignature.check("another key, long enough".getBytes(StandardCharsets.UTF_8), TOPIC, signed)
                .valid());
        assertFalse(JsonSignature.check(KEY, TOPIC, signed.replace("OPEN", "CLEARED")).valid());
        JsonSignature.Checked unknownSender = JsonSignature.check(null, TOPIC, signed);
        assertTrue(unknownSender.signed());
        assertFalse(unknownSender.valid());
        assertFalse(JsonSignature.check(KEY, TOPIC, "{\"state\":\"OPEN\"}").signed());
    }

    @Test
    void aKeyIsTheFirstLineOfItsFileAndAShortOrMissingOneIsRefusedInPlainWords(@TempDir Path dir)
            throws IOException {
        Path file = dir.resolve("flat-7.key");
        Files.writeString(file, "  0123456789abcdef0123 \r\nsecond line\n");
        assertArrayEquals(KEY, JsonSignature.readKey(file, "MQTT key"));

        Files.writeString(file, "0123456789abcde\n" + "0123456789abcdef0123");
        IOException shortKey = assertThrows(IOException.class, () -> JsonSignature.readKey(file, "MQTT key"));
        assertEquals("the MQTT key file " + file + " holds 15 characters, at least 16 are needed "
                + "(e.g. openssl rand -hex 32)", shortKey.getMessage());

        Path missing = dir.resolve("flat-8.key");
        IOException none = assertThrows(IOException.class, () -> JsonSignature.readKey(missing, "key"));
        assertEquals("the key file " + missing + " does not exist", none.getMessage());
    }
}

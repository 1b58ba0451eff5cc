package org.tinysep.json;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

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
}

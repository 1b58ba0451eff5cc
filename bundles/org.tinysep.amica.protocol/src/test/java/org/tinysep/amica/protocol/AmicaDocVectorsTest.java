package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * Keeps {@code docs/protocols/amica.md} honest: every vector in its fenced {@code vector} blocks must decode and
 * encode exactly as the document states.
 */
class AmicaDocVectorsTest {

    private static final Path DOC = Path.of(System.getProperty("basedir", "."), "../../docs/protocols/amica.md");
    private static final Pattern FRAME =
            Pattern.compile("ng=(\\d+) src=(\\d+) dst=(\\d+) seq=(\\d+)");

    /** Reads every vector: a map of key to value per vector, in document order. */
    static List<Map<String, String>> vectors() throws IOException {
        List<Map<String, String>> out = new ArrayList<>();
        boolean inBlock = false;
        Map<String, String> current = new LinkedHashMap<>();
        for (String line : Files.readAllLines(DOC, StandardCharsets.UTF_8)) {
            if (!inBlock) {
                inBlock = line.trim().equals("```vector");
                continue;
            }
            if (line.trim().startsWith("```") || line.isBlank()) {
                if (!current.isEmpty()) {
                    out.add(current);
                    current = new LinkedHashMap<>();
                }
                inBlock = !line.trim().startsWith("```");
                continue;
            }
            int colon = line.indexOf(':');
            assertTrue(colon > 0, "vector line without key: " + line);
            String key = line.substring(0, colon).trim();
            assertTrue(current.put(key, line.substring(colon + 1).trim()) == null, "duplicate key " + key);
        }
        assertTrue(!inBlock, "unterminated vector block");
        return out;
    }

    @Test
    void documentHasTheRequiredVectors() throws IOException {
        List<Map<String, String>> vectors = vectors();
        assertTrue(vectors.size() >= 20, "vectors found: " + vectors.size());
        String names = vectors.stream().map(v -> v.get("name")).collect(Collectors.joining("\n"));
        for (String required : List.of("keep-alive from 1.17, product id MOVEMENT|DOOR", "movement detected by 1.17",
                "reed switch of 1.18 open", "light command 5 2 0 40 from the platform to 1.20")) {
            assertTrue(names.contains(required), "missing vector: " + required);
        }
        for (RejectReason r : RejectReason.values()) {
            if (r != RejectReason.UNKNOWN_NODE) {
                assertTrue(vectors.stream().anyMatch(v -> r.name().equals(v.get("reject"))
                        || r.name().equals(v.get("payload-reject"))), "no vector rejected with " + r);
            }
        }
    }

    @Test
    void everyVectorDecodesAndEncodesAsDocumented() throws Exception {
        for (Map<String, String> v : vectors()) {
            String name = v.get("name");
            assertTrue(name != null && v.containsKey("hex") && v.containsKey("dec"), "incomplete vector " + v);
            byte[] bytes = TestBytes.hex(v.get("hex"));
            assertArrayEquals(bytes, TestBytes.dec(v.get("dec")), name + ": hex and dec differ");
            if (v.containsKey("reject")) {
                AmicaProtocolException e = assertThrows(AmicaProtocolException.class,
                        () -> AmicaCodec.decode(bytes, 0, bytes.length), name);
                assertEquals(RejectReason.valueOf(v.get("reject")), e.reason(), name);
                continue;
            }
            checkFrame(name, v, bytes);
        }
    }

    private static void checkFrame(String name, Map<String, String> v, byte[] bytes) throws Exception {
        Matcher m = FRAME.matcher(v.getOrDefault("frame", ""));
        if (!m.matches()) {
            fail(name + ": needs 'frame: ng=.. src=.. dst=.. seq=..' or 'reject:'");
        }
        byte[] payload = Arrays.copyOfRange(bytes, Math.min(AmicaCodec.HEADER_LENGTH, bytes.length), bytes.length);
        AmicaFrame expected = new AmicaFrame(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)),
                Integer.parseInt(m.group(3)), Integer.parseInt(m.group(4)), payload);
        assertEquals(expected, AmicaCodec.decode(bytes, 0, bytes.length), name + ": decode");
        assertArrayEquals(bytes, AmicaCodec.encode(expected), name + ": encode");

        if (v.containsKey("payload-reject")) {
            AmicaProtocolException e =
                    assertThrows(AmicaProtocolException.class, () -> AmicaPayloads.decode(payload), name);
            assertEquals(RejectReason.valueOf(v.get("payload-reject")), e.reason(), name);
            return;
        }
        AmicaPayload decoded = AmicaPayloads.decode(payload);
        assertEquals(v.get("payload"), decoded.toString(), name + ": payload");
        assertArrayEquals(payload, AmicaPayloads.encode(decoded), name + ": payload encode");
        if (decoded instanceof KeepAlive k) {
            String types = k.nodeTypes().isEmpty() ? "none"
                    : k.nodeTypes().stream().map(Enum::name).collect(Collectors.joining(", "));
            assertEquals(v.get("types"), types, name + ": types");
        }
    }

    @Test
    void streamDecoderFindsEveryValidFrameOfTheDocumentInOneStream() throws Exception {
        List<byte[]> valid = new ArrayList<>();
        for (Map<String, String> v : vectors()) {
            if (!v.containsKey("reject")) {
                valid.add(TestBytes.hex(v.get("hex")));
            }
        }
        RecordingSink sink = new RecordingSink();
        AmicaStreamDecoder decoder = new AmicaStreamDecoder(sink);
        byte[] stream = TestBytes.concat(valid.toArray(new byte[0][]));
        decoder.accept(stream, 0, stream.length);
        assertEquals(valid.size(), sink.frames);
        assertEquals(0, sink.skipped);
    }
}

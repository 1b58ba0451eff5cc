package org.tinysep.sunspot.protocol;

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
 * Keeps {@code docs/protocols/sunspot.md} honest: every vector in its fenced {@code vector} blocks must decode and
 * encode exactly as the document states.
 */
class SunSpotDocVectorsTest {

    private static final Path DOC = Path.of(System.getProperty("basedir", "."), "../../docs/protocols/sunspot.md");
    private static final Pattern FRAME = Pattern.compile("source=([0-9A-Fa-f.]+) type=(\\d+)");

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
        String payloads = vectors.stream().map(v -> v.getOrDefault("payload", ""))
                .collect(Collectors.joining("\n"));
        for (String required : List.of("MovementDetection[detected=true, position=null]",
                "TemperatureStatus[celsius=21.5]", "LightStatus[percent=", "PetMovementDetection[",
                "position=Position[")) {
            assertTrue(payloads.contains(required), "no valid vector with " + required);
        }
        for (RejectReason r : RejectReason.values()) {
            assertTrue(vectors.stream().anyMatch(v -> r.name().equals(v.get("reject"))
                    || r.name().equals(v.get("payload-reject"))), "no vector rejected with " + r);
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
                SunSpotProtocolException e = assertThrows(SunSpotProtocolException.class,
                        () -> SunSpotCodec.decode(bytes, 0, bytes.length), name);
                assertEquals(RejectReason.valueOf(v.get("reject")), e.reason(), name);
                continue;
            }
            checkFrame(name, v, bytes);
        }
    }

    private static void checkFrame(String name, Map<String, String> v, byte[] bytes) throws Exception {
        Matcher m = FRAME.matcher(v.getOrDefault("frame", ""));
        if (!m.matches()) {
            fail(name + ": needs 'frame: source=.... type=..' or 'reject:'");
        }
        byte[] payload = Arrays.copyOfRange(bytes, Math.min(SunSpotCodec.HEADER_LENGTH, bytes.length), bytes.length);
        SunSpotFrame expected =
                new SunSpotFrame(SunSpotAddress.parse(m.group(1)), Integer.parseInt(m.group(2)), payload);
        assertEquals(expected, SunSpotCodec.decode(bytes, 0, bytes.length), name + ": decode");
        assertArrayEquals(bytes, SunSpotCodec.encode(expected), name + ": encode");

        if (v.containsKey("payload-reject")) {
            SunSpotProtocolException e =
                    assertThrows(SunSpotProtocolException.class, () -> SunSpotPayloads.decode(payload), name);
            assertEquals(RejectReason.valueOf(v.get("payload-reject")), e.reason(), name);
            return;
        }
        SunSpotPayload decoded = SunSpotPayloads.decode(payload);
        assertEquals(v.get("payload"), decoded.toString(), name + ": payload");
        assertArrayEquals(payload, SunSpotPayloads.encode(decoded), name + ": payload encode");
        assertEquals(decoded.sensorType().code(), expected.sensorType(), name + ": sensor type");
    }

    @Test
    void streamDecoderFindsEveryValidFrameOfKnownTypeInOneStream() throws Exception {
        List<byte[]> valid = new ArrayList<>();
        for (Map<String, String> v : vectors()) {
            byte[] bytes = TestBytes.hex(v.get("hex"));
            if (!v.containsKey("reject") && SunSpotSensorType.isKnown(bytes[9])) {
                valid.add(bytes);
            }
        }
        assertTrue(valid.size() >= 15, "valid frames of a known type: " + valid.size());
        RecordingSink sink = new RecordingSink();
        SunSpotStreamDecoder decoder = new SunSpotStreamDecoder(sink);
        byte[] stream = TestBytes.concat(valid.toArray(new byte[0][]));
        decoder.accept(stream, 0, stream.length);
        assertEquals(valid.size(), sink.frames);
        assertEquals(0, sink.skipped);
    }
}

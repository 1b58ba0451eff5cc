package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.testing.DocVectors;

/**
 * Keeps {@code docs/protocols/sunspot.md} honest: every vector in its fenced {@code vector} blocks must decode and
 * encode exactly as the document states (the runner, {@link DocVectors}, is shared with the AmICA protocol).
 */
class SunSpotDocVectorsTest implements DocVectors.Family {

    private static final Pattern FRAME = Pattern.compile("source=([0-9A-Fa-f.]+) type=(\\d+)");

    /** Reads every vector: a map of key to value per vector, in document order. */
    static List<Map<String, String>> vectors() throws IOException {
        return DocVectors.read("sunspot.md");
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
        DocVectors.assertEveryReasonUsed(vectors, RejectReason.values(), List.of());
    }

    @Test
    void everyVectorDecodesAndEncodesAsDocumented() throws Exception {
        DocVectors.check(vectors(), this);
    }

    @Override
    public String rejection(String name, byte[] bytes) {
        return assertThrows(SunSpotProtocolException.class, () -> SunSpotCodec.decode(bytes, 0, bytes.length), name)
                .reason().name();
    }

    @Override
    public void valid(String name, Map<String, String> v, byte[] bytes) throws Exception {
        Matcher m = FRAME.matcher(v.getOrDefault("frame", ""));
        DocVectors.requireFrame(m.matches(), name, "source=.... type=..");
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
        DocVectors.assertStreamFindsEvery(vectors(), bytes -> SunSpotSensorType.isKnown(bytes[9]), 15, stream -> {
            RecordingSink sink = new RecordingSink();
            new SunSpotStreamDecoder(sink).accept(stream, 0, stream.length);
            return new long[] {sink.frames, sink.skipped};
        });
    }
}

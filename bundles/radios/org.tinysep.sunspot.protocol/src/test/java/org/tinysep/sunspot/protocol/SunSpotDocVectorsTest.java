package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.testing.Codecs;
import org.tinysep.link.frame.testing.DocVectors;
import org.tinysep.link.frame.testing.DocVectorsContract;

/**
 * Keeps {@code docs/protocols/sunspot.md} honest: every vector in its fenced {@code vector} blocks must decode and
 * encode exactly as the document states (the runner, {@link DocVectors}, is shared with the AmICA protocol).
 */
class SunSpotDocVectorsTest extends DocVectorsContract<SunSpotFrame, SunSpotPayload> {

    /** The Sun SPOT codecs as the shared runners see them. */
    static final Codecs<SunSpotFrame, SunSpotPayload, SunSpotProtocolException> CODECS =
            new Codecs<>(SunSpotCodec::decode, SunSpotCodec::encode, SunSpotPayloads::decode, SunSpotPayloads::encode,
                    SunSpotCodec.HEADER_LENGTH, SunSpotProtocolException.class, SunSpotProtocolException::reason);

    private static final Pattern FRAME = Pattern.compile("source=([0-9A-Fa-f.]+) type=(\\d+)");

    SunSpotDocVectorsTest() {
        super("sunspot.md", CODECS);
    }

    @Test
    void documentHasTheRequiredVectors() throws IOException {
        DocVectors.assertRequired(vectors(), "payload", List.of("MovementDetection[detected=true, position=null]",
                "TemperatureStatus[celsius=21.5]", "LightStatus[percent=", "PetMovementDetection[",
                "position=Position[", "ButtonReport[button=1, pressed=true]", "ButtonReport[button=2, pressed=false]",
                "MovementSummaryReport[", "BurstChunk[burstId=3, chunkIndex=0, chunkCount=1", "chunkIndex=4, chunkCount=5"));
        DocVectors.assertEveryReasonUsed(vectors(), RejectReason.values(), List.of());
    }

    @Override
    public SunSpotFrame frame(String name, Map<String, String> v, byte[] payload) {
        Matcher m = DocVectors.frameLine(FRAME, name, v, "source=.... type=..");
        return new SunSpotFrame(SunSpotAddress.parse(m.group(1)), Integer.parseInt(m.group(2)), payload);
    }

    @Override
    public void payload(String name, Map<String, String> v, SunSpotFrame frame, SunSpotPayload decoded) {
        assertEquals(decoded.sensorType().code(), frame.sensorType(), name + ": sensor type");
    }

    @Test
    void streamDecoderFindsEveryValidFrameOfKnownTypeInOneStream() throws Exception {
        DocVectors.assertStreamFindsEvery(vectors(), bytes -> SunSpotSensorType.isKnown(bytes[9]), 15,
                RecordingSink::new, SunSpotStreamDecoder::new);
    }
}

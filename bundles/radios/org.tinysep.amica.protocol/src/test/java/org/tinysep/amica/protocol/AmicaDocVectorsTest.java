package org.tinysep.amica.protocol;

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
 * Keeps {@code docs/protocols/amica.md} honest: every vector in its fenced {@code vector} blocks must decode and
 * encode exactly as the document states (the runner, {@link DocVectors}, is shared with the Sun SPOT protocol).
 */
class AmicaDocVectorsTest extends DocVectorsContract<AmicaFrame, AmicaPayload> {

    /** The AmICA codecs as the shared runners see them. */
    static final Codecs<AmicaFrame, AmicaPayload, AmicaProtocolException> CODECS = new Codecs<>(AmicaCodec::decode,
            AmicaCodec::encode, AmicaPayloads::decode, AmicaPayloads::encode, AmicaCodec.HEADER_LENGTH,
            AmicaProtocolException.class, AmicaProtocolException::reason);

    private static final Pattern FRAME =
            Pattern.compile("ng=(\\d+) src=(\\d+) dst=(\\d+) seq=(\\d+)");

    AmicaDocVectorsTest() {
        super("amica.md", CODECS);
    }

    @Test
    void documentHasTheRequiredVectors() throws IOException {
        List<Map<String, String>> vectors = vectors();
        DocVectors.assertRequired(vectors, "name", List.of("keep-alive from 1.17, product id MOVEMENT|DOOR",
                "movement detected by 1.17", "reed switch of 1.18 open",
                "light command 5 2 0 40 from the platform to 1.20"));
        DocVectors.assertEveryReasonUsed(vectors, RejectReason.values(), List.of(RejectReason.UNKNOWN_NODE));
    }

    @Override
    public AmicaFrame frame(String name, Map<String, String> v, byte[] payload) {
        Matcher m = DocVectors.frameLine(FRAME, name, v, "ng=.. src=.. dst=.. seq=..");
        return new AmicaFrame(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)),
                Integer.parseInt(m.group(3)), Integer.parseInt(m.group(4)), payload);
    }

    @Override
    public void payload(String name, Map<String, String> v, AmicaFrame frame, AmicaPayload decoded) {
        if (decoded instanceof KeepAlive k) {
            String types = k.nodeTypes().isEmpty() ? "none"
                    : k.nodeTypes().stream().map(Enum::name).collect(Collectors.joining(", "));
            assertEquals(v.get("types"), types, name + ": types");
        }
    }

    @Test
    void streamDecoderFindsEveryValidFrameOfTheDocumentInOneStream() throws Exception {
        DocVectors.assertStreamFindsEvery(vectors(), bytes -> true, 0, RecordingSink::new, AmicaStreamDecoder::new);
    }
}

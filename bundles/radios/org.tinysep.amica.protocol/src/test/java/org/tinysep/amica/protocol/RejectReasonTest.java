package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.testing.DocVectors;
import org.tinysep.link.frame.testing.ReasonChecks;

/**
 * Every reject reason is provoked by real input (the rejected vectors of {@code docs/protocols/amica.md}), and
 * every reason reads well in a log; the checks are {@link ReasonChecks}, shared with the Sun SPOT protocol.
 */
class RejectReasonTest {

    @Test
    void everyReasonIsProvoked() throws IOException {
        // UNKNOWN_NODE is raised by the bus radios, which construct the exception themselves
        AmicaProtocolException unknown = new AmicaProtocolException(RejectReason.UNKNOWN_NODE, "node 1.99");
        ReasonChecks.assertEveryReasonProvoked(DocVectors.read("amica.md"), AmicaDocVectorsTest.CODECS,
                RejectReason.values(), unknown.reason());
        assertEquals("UNKNOWN_NODE (packet from an unknown node that is not a keep-alive): node 1.99",
                unknown.getMessage());
    }

    @Test
    void everyReasonHasADistinctDescription() {
        ReasonChecks.assertDistinctDescriptions(RejectReason.values(), RejectReason::description);
        assertEquals("frame shorter than its size identifier announces", RejectReason.TRUNCATED.description());
    }

    @Test
    void messageWithoutDetailIsReasonAndDescription() {
        assertEquals("BAD_VALUE (payload has a wrong length or a value out of range)",
                new AmicaProtocolException(RejectReason.BAD_VALUE, null).getMessage());
        assertThrows(NullPointerException.class, () -> new AmicaProtocolException(null, "x"));
    }
}

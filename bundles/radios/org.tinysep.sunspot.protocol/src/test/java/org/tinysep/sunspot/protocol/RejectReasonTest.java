package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import org.junit.jupiter.api.Test;
import org.tinysep.link.frame.testing.DocVectors;
import org.tinysep.link.frame.testing.ReasonChecks;

/**
 * Every reject reason is provoked by real input (the rejected vectors of {@code docs/protocols/sunspot.md}), and
 * every reason reads well in a log; the checks are {@link ReasonChecks}, shared with the AmICA protocol.
 */
class RejectReasonTest {

    @Test
    void everyReasonIsProvoked() throws IOException {
        ReasonChecks.assertEveryReasonProvoked(DocVectors.read("sunspot.md"), SunSpotDocVectorsTest.CODECS,
                RejectReason.values());
    }

    @Test
    void everyReasonHasADistinctDescription() {
        ReasonChecks.assertDistinctDescriptions(RejectReason.values(), RejectReason::description);
        assertEquals("header sensor type differs from the payload's first byte",
                RejectReason.TYPE_MISMATCH.description());
    }

    @Test
    void messageIsReasonDescriptionAndDetail() {
        assertEquals("BAD_VALUE (payload has a wrong length or a value out of range)",
                new SunSpotProtocolException(RejectReason.BAD_VALUE, null).getMessage());
        assertEquals("UNKNOWN_PAYLOAD (payload type is not one of thesis Table 3.2): type 9",
                new SunSpotProtocolException(RejectReason.UNKNOWN_PAYLOAD, "type 9").getMessage());
        assertThrows(NullPointerException.class, () -> new SunSpotProtocolException(null, "x"));
    }
}

package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.link.frame.testing.TestBytes.dec;
import static org.tinysep.link.frame.testing.TestBytes.hex;

import java.util.EnumSet;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Every reject reason is provoked by real input, and every reason reads well in a log. */
class RejectReasonTest {

    private static RejectReason frameReason(String hexBytes) {
        byte[] b = hex(hexBytes);
        return assertThrows(SunSpotProtocolException.class, () -> SunSpotCodec.decode(b, 0, b.length)).reason();
    }

    private static RejectReason payloadReason(String decimal) {
        byte[] b = dec(decimal);
        return assertThrows(SunSpotProtocolException.class, () -> SunSpotPayloads.decode(b)).reason();
    }

    @Test
    void everyReasonIsProvoked() {
        Set<RejectReason> seen = EnumSet.noneOf(RejectReason.class);
        seen.add(frameReason("04 00 14 4F 01 00 00 12 34 02 38 04 02 01 00"));
        seen.add(frameReason("04 00 14 4F 01 00 00 12 34 02 38 04 02 01 00 01 00"));
        seen.add(frameReason("04 00 14 4F 01 00 00 12 34 02 38 05 02 01 00 01"));
        seen.add(frameReason("04 00 14 4F 01 00 00 12 34 02 39 04 02 01 00 01"));
        seen.add(frameReason("04 00 14 4F 01 00 00 12 34 03 11 04 02 01 00 01"));
        seen.add(payloadReason("9 1 0 0"));
        seen.add(payloadReason("2 1 0 2"));
        assertEquals(EnumSet.allOf(RejectReason.class), seen);
    }

    @Test
    void everyReasonHasADistinctDescription() {
        Set<String> texts = new HashSet<>();
        for (RejectReason r : RejectReason.values()) {
            assertFalse(r.description().isBlank(), r.name());
            assertTrue(texts.add(r.description()), "duplicate description of " + r);
        }
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

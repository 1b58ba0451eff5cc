package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.link.frame.testing.TestBytes.dec;
import static org.tinysep.link.frame.testing.TestBytes.hex;

import java.util.EnumSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Every reject reason is provoked by real input, and every reason reads well in a log. */
class RejectReasonTest {

    private static RejectReason frameReason(String hexBytes) {
        byte[] b = hex(hexBytes);
        return assertThrows(AmicaProtocolException.class, () -> AmicaCodec.decode(b, 0, b.length)).reason();
    }

    private static RejectReason payloadReason(String decimal) {
        byte[] b = dec(decimal);
        return assertThrows(AmicaProtocolException.class, () -> AmicaPayloads.decode(b)).reason();
    }

    @Test
    void everyReasonIsProvoked() {
        Set<RejectReason> seen = EnumSet.noneOf(RejectReason.class);
        seen.add(frameReason("04 A1 11 00 01 06 2B 04 64 05 00"));
        seen.add(frameReason("04 A1 11 00 01 06 2B 04 64 05 00 01 00"));
        seen.add(frameReason("04 A2 11 00 01 06 2B 04 64 05 00 01"));
        seen.add(frameReason("04 A1 11 00 01 06 2B 03 64 05 00 01"));
        seen.add(frameReason("04 A1 11 00 01 06 2C 04 64 05 00 01"));
        seen.add(payloadReason("9 9 0 0"));
        seen.add(payloadReason("100 5 0 2"));
        // UNKNOWN_NODE is raised by the bus radios, which construct the exception themselves
        AmicaProtocolException unknown = new AmicaProtocolException(RejectReason.UNKNOWN_NODE, "node 1.99");
        seen.add(unknown.reason());
        assertEquals(EnumSet.allOf(RejectReason.class), seen);
        assertEquals("UNKNOWN_NODE (packet from an unknown node that is not a keep-alive): node 1.99",
                unknown.getMessage());
    }

    @Test
    void everyReasonHasADistinctDescription() {
        Set<String> texts = new java.util.HashSet<>();
        for (RejectReason r : RejectReason.values()) {
            assertFalse(r.description().isBlank(), r.name());
            assertTrue(texts.add(r.description()), "duplicate description of " + r);
        }
        assertEquals("frame shorter than its size identifier announces", RejectReason.TRUNCATED.description());
    }

    @Test
    void messageWithoutDetailIsReasonAndDescription() {
        assertEquals("BAD_VALUE (payload has a wrong length or a value out of range)",
                new AmicaProtocolException(RejectReason.BAD_VALUE, null).getMessage());
        assertThrows(NullPointerException.class, () -> new AmicaProtocolException(null, "x"));
    }
}

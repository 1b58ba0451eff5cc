package org.tinysep.link.frame.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Map;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Function;

/** Checks both protocol families' tests make of their reject reasons. */
public final class ReasonChecks {

    private ReasonChecks() {
    }

    /**
     * Every reason is provoked by real input: the reasons the family's codecs raise on the rejected vectors of its
     * document (a frame's {@code reject}, a payload's {@code payload-reject}), plus those raised elsewhere, are all
     * the reasons there are.
     *
     * @param raisedElsewhere reasons other code raises with the family's exception (e.g. the bus radios)
     */
    public static void assertEveryReasonProvoked(List<Map<String, String>> vectors, Codecs<?, ?, ?> codecs,
            Enum<?>[] all, Enum<?>... raisedElsewhere) {
        Set<String> seen = new TreeSet<>();
        for (Map<String, String> v : vectors) {
            byte[] bytes = TestBytes.hex(v.get("hex"));
            if (v.containsKey("reject")) {
                seen.add(codecs.frameRejection(v.get("name"), bytes).name());
            } else if (v.containsKey("payload-reject")) {
                seen.add(codecs.payloadRejection(v.get("name"), codecs.payloadOf(bytes)).name());
            }
        }
        for (Enum<?> r : raisedElsewhere) {
            seen.add(r.name());
        }
        Set<String> names = new TreeSet<>();
        for (Enum<?> r : all) {
            names.add(r.name());
        }
        assertEquals(names, seen);
    }

    /** Every reason reads well in a log: it has a description, and no two reasons share one. */
    public static <R extends Enum<R>> void assertDistinctDescriptions(R[] all, Function<R, String> description) {
        Set<String> texts = new HashSet<>();
        for (R r : all) {
            assertFalse(description.apply(r).isBlank(), r.name());
            assertTrue(texts.add(description.apply(r)), "duplicate description of " + r);
        }
    }
}

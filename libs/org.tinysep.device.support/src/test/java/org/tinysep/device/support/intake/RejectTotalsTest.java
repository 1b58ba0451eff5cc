package org.tinysep.device.support.intake;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Parameter;

/** The {@code rejected} total is the sum of every {@code rejected.<reason>} a driver shows (issue 25, item 8). */
class RejectTotalsTest {

    private static Parameter p(String key, Object value) {
        return Parameter.readOnly(key, value, key + " description");
    }

    @Test
    void theTotalAddsEveryCounterIncludingTheNodeCapAndTheSourceGate() {
        List<Parameter> out = RejectTotals.summed(List.of(p("received", 100), p("rejected", 3),
                p("rejected.bad_checksum", 3), p("sources", "127.0.0.1"), p("rejected.source_not_allowed", 10),
                p("rejected.rate_limited", 5), p("maxNodes", 2), p("rejected.node_cap", 7)));
        assertEquals(List.of("received", "rejected", "rejected.bad_checksum", "sources", "rejected.source_not_allowed",
                "rejected.rate_limited", "maxNodes", "rejected.node_cap"), out.stream().map(Parameter::key).toList());
        assertEquals("25", out.get(1).value());
        assertEquals("rejected description", out.get(1).description(), "the total keeps its description");
        assertEquals("100", out.get(0).value(), "other parameters unchanged");
    }

    @Test
    void withoutATotalOneIsAddedBeforeTheFirstCounter() {
        List<Parameter> out = RejectTotals.summed(List.of(p("nodes", 1), p("rejected.node_cap", 2), p("x", "y")));
        assertEquals(List.of("nodes", "rejected", "rejected.node_cap", "x"), out.stream().map(Parameter::key).toList());
        assertEquals("2", out.get(1).value());
        assertEquals("0", RejectTotals.summed(List.of(p("nodes", 1))).get(1).value());
    }
}

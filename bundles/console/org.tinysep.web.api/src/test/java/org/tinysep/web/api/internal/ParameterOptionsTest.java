package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Parameter;

class ParameterOptionsTest {

    private static List<String> options(String description) {
        return ParameterOptions.of(Parameter.writable("k", "", description));
    }

    @Test
    void readsTheChoicesDriversWriteAtTheStartOfTheDescription() {
        assertEquals(List.of("OUTER", "INNER"), options("OUTER (to the outside; watched by Flat Occupancy) or INNER"));
        assertEquals(List.of("INSIDE", "OUTSIDE"), options("INSIDE or OUTSIDE the flat"));
        assertEquals(List.of("REAL", "EXTERNAL"), options("REAL or EXTERNAL (lock-step with the time synchroniser)"));
        assertEquals(List.of("true", "false"), options("true or false; shows the node's report, a change waits"));
        assertEquals(List.of("AB", "B2", "C_D"), options("AB, B2 (second) or C_D"));
    }

    @Test
    void freeTextAndReadOnlyParametersHaveNoChoices() {
        assertEquals(List.of(), options("name shown to the user"));
        assertEquals(List.of(), options("room of the device: UID, unique UID prefix or name; empty to clear"));
        assertEquals(List.of(), options("0..100 %; shows the node's report"));
        assertEquals(List.of(), options("x,y,z in metres in the house's frame, empty when unknown"));
        assertEquals(List.of(), options("ORDINARY words or MORE"));
        assertEquals(List.of(), ParameterOptions.of(Parameter.readOnly("k", "", "INSIDE or OUTSIDE the flat")));
    }
}

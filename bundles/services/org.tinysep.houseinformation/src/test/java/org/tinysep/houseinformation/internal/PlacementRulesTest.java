package org.tinysep.houseinformation.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class PlacementRulesTest {

    private static Optional<String> roomOf(PlacementRules rules, String address) {
        return rules.ruleFor(address).map(PlacementRules.Rule::room);
    }

    @Test
    void commaAndNewlineSeparatedEntriesAreParsed() {
        PlacementRules rules = PlacementRules.parse(
                "1.10=Hall, 1.20 = Living Room\n0014.4f01.0000.0001=Kitchen\r\n\n , 2.3=decb2a7f");
        assertEquals(List.of(), rules.errors());
        assertEquals(4, rules.size());
        assertEquals(Optional.of("Hall"), roomOf(rules, "1.10"));
        assertEquals(Optional.of("Living Room"), roomOf(rules, "1.20"));
        assertEquals(Optional.of("Kitchen"), roomOf(rules, "0014.4F01.0000.0001"), "Sun SPOT hex in any case");
        assertEquals(Optional.of("Kitchen"), roomOf(rules, "0014.4f01.0000.0001"));
        assertEquals(Optional.of("decb2a7f"), roomOf(rules, "2.3"));
        assertEquals(Optional.empty(), roomOf(rules, "1.11"));
        assertEquals(Optional.empty(), rules.ruleFor(null));
    }

    @Test
    void amicaAddressesAreComparedAsNumbers() {
        PlacementRules rules = PlacementRules.parse("01.010=Hall");
        assertEquals(Optional.of("Hall"), roomOf(rules, "1.10"));
        assertEquals(Optional.of("1.10"), rules.ruleFor("1.10").map(PlacementRules.Rule::address));
    }

    @Test
    void emptyConfigurationHasNoRulesAndNoErrors() {
        for (String text : new String[] {null, "", "  ", ",\n,"}) {
            PlacementRules rules = PlacementRules.parse(text);
            assertEquals(0, rules.size());
            assertEquals(List.of(), rules.errors());
        }
    }

    @Test
    void badEntriesGetClearMessagesAndTheRestStillApplies() {
        PlacementRules rules = PlacementRules.parse(
                "1.10 Hall, 1.17=Hall, 256.1=Hall, =Kitchen, 1.18=, 0014.4F01.0000=Bath, 1.17=Kitchen, 1.19=Bath");
        assertEquals(2, rules.size());
        assertEquals(Optional.of("Hall"), roomOf(rules, "1.17"), "the first entry for a node applies");
        assertEquals(Optional.of("Bath"), roomOf(rules, "1.19"));
        List<String> errors = rules.errors();
        assertEquals(6, errors.size(), errors.toString());
        assertEquals("placement entry '1.10 Hall' has no '=': expected <node address>=<room>", errors.get(0));
        assertTrue(errors.get(1).startsWith("placement entry '256.1=Hall': '256.1' is not a node address"),
                errors.get(1));
        assertTrue(errors.get(2).contains("'' is not a node address"), errors.get(2));
        assertEquals("placement entry '1.18=' names no room", errors.get(3));
        assertTrue(errors.get(4).contains("'0014.4F01.0000' is not a node address (AmICA NG.ADDR like 1.17, "
                + "or Sun SPOT XXXX.XXXX.XXXX.XXXX)"), errors.get(4));
        assertEquals("placement entry '1.17=Kitchen': node 1.17 is already placed by '1.17=Hall'; the first entry"
                + " applies", errors.get(5));
    }

    @Test
    void addressesAreNormalisedOrRefused() {
        assertEquals(Optional.of("0.0"), PlacementRules.normalise(" 0.0 "));
        assertEquals(Optional.of("255.255"), PlacementRules.normalise("255.255"));
        assertEquals(Optional.of("ABCD.0000.1234.FFFF"), PlacementRules.normalise("abcd.0000.1234.ffff"));
        for (String bad : new String[] {"1", "1.2.3", "1.256", "a.b", "1.-2", "ABCD.0000.1234.FFFG", "1,2"}) {
            assertEquals(Optional.empty(), PlacementRules.normalise(bad), bad);
        }
    }
}

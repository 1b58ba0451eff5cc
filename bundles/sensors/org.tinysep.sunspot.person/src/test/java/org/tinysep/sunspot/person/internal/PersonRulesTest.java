package org.tinysep.sunspot.person.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The configured wearers (key persons): addresses in any case, bad entries said in words, the others applied. */
class PersonRulesTest {

    @Test
    void namesNodesByAddressAndSaysWhatIsWrongWithTheRest() {
        PersonRules r = PersonRules.parse(" 0014.4f01.0000.0a04 = Anna ,\n0014.4F01.0000.0B01=Ben, nonsense, "
                + "1.17=Otto, 0014.4F01.0000.0A04=Eva, 0014.4F01.0000.0C01=");
        assertEquals(Optional.of("Anna"), r.nameOf("0014.4F01.0000.0A04"));
        assertEquals(Optional.of("Ben"), r.nameOf("0014.4f01.0000.0b01"));
        assertEquals(Optional.empty(), r.nameOf("0014.4F01.0000.0D01"));
        assertEquals(Optional.empty(), r.nameOf("not an address"));
        assertEquals(List.of("persons entry 'nonsense' is not <node address>=<name>",
                "persons entry '1.17=Otto': '1.17' is not a Sun SPOT address (XXXX.XXXX.XXXX.XXXX, hex)",
                "persons entry '0014.4F01.0000.0A04=Eva': node 0014.4F01.0000.0A04 is named twice; the first, Anna, "
                        + "applies",
                "persons entry '0014.4F01.0000.0C01=' is not <node address>=<name>"), r.problems());
        assertEquals(List.of(), PersonRules.parse("").problems());
        assertEquals(1, PersonRules.parse("0014.4F01.0000.0A04=" + "x".repeat(61)).problems().size());
    }
}

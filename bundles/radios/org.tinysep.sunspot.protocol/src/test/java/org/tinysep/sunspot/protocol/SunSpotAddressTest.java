package org.tinysep.sunspot.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

class SunSpotAddressTest {

    @Test
    void writesFourGroupsOfFourUpperCaseHexDigits() {
        assertEquals("0014.4F01.0000.1234", new SunSpotAddress(0x0014_4F01_0000_1234L).toString());
        assertEquals("0000.0000.0000.0000", new SunSpotAddress(0).toString());
        assertEquals("FFFF.FFFF.FFFF.FFFF", new SunSpotAddress(-1).toString());
        assertEquals("8000.0000.0000.00AB", new SunSpotAddress(0x8000_0000_0000_00ABL).toString());
    }

    @Test
    void parsesBothCasesAndRoundTrips() {
        assertEquals(new SunSpotAddress(0x0014_4F01_0000_1234L), SunSpotAddress.parse("0014.4F01.0000.1234"));
        assertEquals(new SunSpotAddress(0x0014_4F01_0000_ABCDL), SunSpotAddress.parse("0014.4f01.0000.abcd"));
        Random random = new Random(3);
        for (int i = 0; i < 1000; i++) {
            SunSpotAddress a = new SunSpotAddress(random.nextLong());
            assertEquals(a, SunSpotAddress.parse(a.toString()));
        }
    }

    @Test
    void rejectsBadTextWithAClearMessage() {
        for (String bad : new String[] {"", "0014.4F01.0000", "0014.4F01.0000.12345", "0014-4F01-0000-1234",
                "0014.4F01.0000.12G4", "00144F0100001234", " 014.4F01.0000.1234", "0014.4F01..000.1234",
                "+014.4F01.0000.1234"}) {
            IllegalArgumentException e =
                    assertThrows(IllegalArgumentException.class, () -> SunSpotAddress.parse(bad), bad);
            assertTrue(e.getMessage().contains("0014.4F01.0000.1234"), e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> SunSpotAddress.parse(null));
    }
}

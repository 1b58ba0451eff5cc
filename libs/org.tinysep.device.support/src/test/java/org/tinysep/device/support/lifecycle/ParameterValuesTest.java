package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.Percent;

class ParameterValuesTest {

    @Test
    void percentAcceptsWholeNumbersWithOrWithoutPercentSign() {
        assertEquals(Percent.of(40), ParameterValues.percent("volume", "40"));
        assertEquals(Percent.of(0), ParameterValues.percent("volume", " 0 "));
        assertEquals(Percent.of(100), ParameterValues.percent("volume", "100 %"));
    }

    @Test
    void percentRejectsEverythingElseWithAClearMessage() {
        for (String bad : new String[] {"101", "-1", "4.5", "", "loud", "%"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> ParameterValues.percent("volume", bad));
            assertEquals("volume must be a whole percentage 0..100, was '" + bad + "'", e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> ParameterValues.percent("volume", null));
    }

    @Test
    void boolAcceptsTrueFalseOnOff() {
        assertTrue(ParameterValues.bool("on", "true"));
        assertTrue(ParameterValues.bool("on", " ON "));
        assertFalse(ParameterValues.bool("on", "False"));
        assertFalse(ParameterValues.bool("on", "off"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ParameterValues.bool("on", "maybe"));
        assertEquals("on must be true or false (or on/off), was 'maybe'", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ParameterValues.bool("on", null));
    }
}

package org.tinysep.api.alert;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.util.Arrays;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** The plain words of each alert kind, which the caregiver page, the MQTT bridge and the board all show. */
class AlertKindTest {

    @Test
    void everyKindHasItsOwnPlainWords() {
        for (AlertKind k : AlertKind.values()) {
            assertFalse(k.words().isBlank(), k.name());
        }
        Set<String> distinct = Arrays.stream(AlertKind.values()).map(AlertKind::words).collect(Collectors.toSet());
        assertEquals(AlertKind.values().length, distinct.size(), "two kinds share their words: " + distinct);
        assertEquals("fall (the person may have fallen)", AlertKind.FALL.words());
        assertEquals("help button (the person asked for help)", AlertKind.HELP.words());
        assertEquals("inactivity (the person may need help)", AlertKind.INACTIVITY.words());
    }
}

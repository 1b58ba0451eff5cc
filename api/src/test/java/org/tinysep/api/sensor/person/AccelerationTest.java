package org.tinysep.api.sensor.person;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The one mean of accelerations: exact sums, rounded once to the nearest milli-g, halves away from zero. */
class AccelerationTest {

    @Test
    void theMeanOfOneSampleIsThatSample() {
        assertEquals(new Acceleration(12, -1003, 7), Acceleration.mean(List.of(new Acceleration(12, -1003, 7))));
    }

    @Test
    void theMeanRoundsToTheNearestMilliGNotDown() {
        // x: 10/3 = 3.33 -> 3; y: 5/3 = 1.67 -> 2 (truncation gave 1); z: -5/3 = -1.67 -> -2 (truncation gave -1)
        List<Acceleration> v = List.of(new Acceleration(3, 2, -2), new Acceleration(3, 2, -2),
                new Acceleration(4, 1, -1));
        assertEquals(new Acceleration(3, 2, -2), Acceleration.mean(v));
    }

    @Test
    void halvesGoAwayFromZeroSoAMirroredListHasTheMirroredMean() {
        List<Acceleration> v = List.of(new Acceleration(2, -2, 0), new Acceleration(3, -3, 1));
        assertEquals(new Acceleration(3, -3, 1), Acceleration.mean(v));
        List<Acceleration> mirrored = List.of(new Acceleration(-2, 2, 0), new Acceleration(-3, 3, -1));
        assertEquals(new Acceleration(-3, 3, -1), Acceleration.mean(mirrored));
    }

    @Test
    void longListsOfLargeValuesDoNotOverflow() {
        // 1,000,000 samples of 16 g on every axis: the int sum would overflow, the long sum does not
        List<Acceleration> v = Collections.nCopies(1_000_000, new Acceleration(16_000, -16_000, 16_000));
        assertEquals(new Acceleration(16_000, -16_000, 16_000), Acceleration.mean(v));
    }

    @Test
    void anEmptyListIsAClearErrorNotAZeroVector() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Acceleration.mean(List.of()));
        assertTrue(e.getMessage().contains("at least one sample"), e.getMessage());
    }
}

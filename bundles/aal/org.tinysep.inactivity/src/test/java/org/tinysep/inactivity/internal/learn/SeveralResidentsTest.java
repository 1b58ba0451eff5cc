package org.tinysep.inactivity.internal.learn;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import org.junit.jupiter.api.Test;

/**
 * Issue 28, item 1 on a home of two residents (session 36): the residents share the sensors, so (1) an activity in a
 * room where a bed or seat mat is ON is a resting person's, and (2) a learned limit is never longer than the fixed
 * one. One resident: nothing changes.
 */
class SeveralResidentsTest {

    private static final Duration FIXED = Duration.ofHours(3);

    /** {@link SittingDownTest}'s 14 afternoons: sit down 14:10 for 3 h in the living room. */
    private static LearnedLimits afternoons(int residents) {
        return new LearnedLimits(SittingDownTest.afternoons(LearningSettings.defaults().withMinPeriodsToShorten(0)
                .withResidents(residents)));
    }

    private static Limit sit(LearnedLimits limits) {
        Instant at = History.at(20, "15:00");
        return limits.limitAfter(new Sighting(at, "Living", "Living", "Living room", false, true), FIXED, at);
    }

    @Test
    void withSeveralResidentsALearnedLimitIsNeverLongerThanTheFixedOne() {
        Limit two = sit(afternoons(2));
        assertEquals(FIXED, two.limit(), two.explanation());
        assertTrue(two.explanation().startsWith("fixed limit of 3 h for Living: the history would lengthen it to "
                + "4 h 40 min, but the home has 2 residents"), two.explanation());
        Limit one = sit(afternoons(1));
        assertEquals(Duration.ofMinutes(280), one.limit(), "one resident: 3 h x 1.5 + 10 min as before: "
                + one.explanation());
    }

    @Test
    void withSeveralResidentsAShorterLearnedLimitStays() {
        Instant at = History.at(20, "14:00");
        Limit walk = afternoons(2).limitAfter(new Sighting(at, "Living", "Living", "Living room", false), FIXED, at);
        assertEquals(Duration.ofMinutes(25), walk.limit(), walk.explanation());
    }

    @Test
    void anActivityWhereASeatMatIsOnIsSittingWithSeveralResidents() {
        Residents two = new Residents(2);
        two.mat("seat", "Living", false, true);
        Sighting pir = new Sighting(History.at(20, "15:27"), "Living", "Living", "Living room", false);
        Sighting read = two.read(pir);
        assertTrue(read.seated() && !read.inBed() && !read.upFromBed(), read.toString());
        assertEquals(pir.at(), read.at());

        Sighting kitchen = new Sighting(pir.at(), "Kitchen", "Kitchen", "Kitchen", false);
        assertSame(kitchen, two.read(kitchen), "no mat ON in the kitchen");
        two.mat("seat", "Living", false, false);
        assertFalse(two.read(pir).seated(), "the seat mat turned OFF");
    }

    @Test
    void oneMatOffLeavesTheOtherOnAndABedComesFirst() {
        Residents two = new Residents(2);
        two.mat("seat", "Living", false, true);
        two.mat("seat 2", "Living", false, true);
        two.mat("seat", "Living", false, false);
        Sighting pir = new Sighting(History.at(20, "15:27"), "Living", "Living", "Living room", false);
        assertTrue(two.read(pir).seated(), "the second seat mat is still ON");
        two.mat("bed", "Living", true, true);
        Sighting read = two.read(pir);
        assertTrue(read.inBed() && !read.seated(), read.toString());
    }

    @Test
    void oneResidentAndAMatsOwnChangeAreLeftAsTheyAre() {
        Residents one = new Residents(1);
        one.mat("seat", "Living", false, true);
        Sighting pir = new Sighting(History.at(20, "15:27"), "Living", "Living", "Living room", false);
        assertSame(pir, one.read(pir), "one resident: the movement is the person getting up");
        Sighting up = new Sighting(pir.at(), "Living", "Living", "Bedroom", false, false, true);
        assertSame(up, Residents.read(up, true, false), "getting up stays getting up");
        assertThrows(IllegalArgumentException.class, () -> new Residents(-1));
        assertThrows(IllegalArgumentException.class, () -> LearningSettings.defaults().withResidents(-1));
    }
}

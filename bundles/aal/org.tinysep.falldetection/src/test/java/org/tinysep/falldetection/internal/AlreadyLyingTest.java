package org.tinysep.falldetection.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.falldetection.internal.Nodes.LYING;
import static org.tinysep.falldetection.internal.Nodes.UPRIGHT;
import static org.tinysep.falldetection.internal.Nodes.burst;
import static org.tinysep.falldetection.internal.Nodes.summary;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.person.Acceleration;

/**
 * An impact while the body was already lying (turning over in bed, getting up from lying: SisFall's D14 and D13)
 * is not a fall; the posture before is judged against the wearer's learned upright.
 */
class AlreadyLyingTest {

    /** Lying on the side: 90° from lying on the back ({@link Nodes#LYING}) and from upright. */
    static final Acceleration ON_THE_SIDE = new Acceleration(990, -60, 100);
    /** Sitting on a tilted wearer: 25° from their upright {@link UprightTest#TILTED}. */
    static final Acceleration SITTING_TILTED = new Acceleration(30, -560, -830);
    private final List<Fall> falls = new ArrayList<>();

    /**
     * Walks for 10 s in {@code upright}, is in {@code before} from 12 s to 30 s, a burst at 30.5 s, then
     * {@code after}, still, from 34 s to 60 s.
     */
    private void play(FallDetector d, Acceleration upright, Acceleration before, Acceleration after) {
        for (int t = 2; t <= 10; t += 2) {
            d.summary(summary(t, upright, 260, 1700)).ifPresent(falls::add);
        }
        for (int t = 12; t <= 30; t += 2) {
            d.summary(summary(t, before, 15, 1020)).ifPresent(falls::add);
        }
        d.summary(summary(32, new Acceleration(500, -300, 700), 600, 2600)).ifPresent(falls::add);
        d.burst(burst(30.5, before, 2600, after)).ifPresent(falls::add);
        for (int t = 34; t <= 60; t += 2) {
            d.summary(summary(t, after, 15, 1020)).ifPresent(falls::add);
        }
    }

    @Test
    void turningOverInBedIsNotAFall() {
        play(new FallDetector(FallDetectorTest.SETTINGS), UPRIGHT, LYING, ON_THE_SIDE);
        assertEquals(List.of(), falls, "lying on the back, a bump, lying on the side");
    }

    @Test
    void gettingUpFromLyingIsNotAFall() {
        play(new FallDetector(FallDetectorTest.SETTINGS), UPRIGHT, LYING, SITTING_TILTED);
        assertEquals(List.of(), falls, "lying, a bump, sitting still on the bed's edge");
    }

    @Test
    void theRuleIsWhatKeepsTheTurnQuiet() {
        play(new FallDetector(FallDetectorTest.SETTINGS.withAlreadyLyingDeg(180)), UPRIGHT, LYING, ON_THE_SIDE);
        assertEquals(1, falls.size(), "with the rule off the turn looks like a fall: " + falls);
    }

    @Test
    void aFallFromSittingOfATiltedWearerIsStillAFall() {
        // the node's fixed y axis would call this sitting posture 56° off; the wearer's own upright says 25°
        play(new FallDetector(FallDetectorTest.SETTINGS.withAlreadyLyingDeg(50)), UprightTest.TILTED,
                SITTING_TILTED, LYING);
        assertEquals(1, falls.size(), "sitting, an impact, lying still: " + falls);
        assertTrue(falls.get(0).angleDeg() > 30, falls.get(0).toString());
    }

    @Test
    void withoutALearnedUprightNothingIsTakenForLying() {
        FallDetector d = new FallDetector(FallDetectorTest.SETTINGS);
        for (int t = 12; t <= 30; t += 2) {
            d.summary(summary(t, LYING, 15, 1020)).ifPresent(falls::add);
        }
        d.burst(burst(30.5, LYING, 2600, ON_THE_SIDE)).ifPresent(falls::add);
        for (int t = 34; t <= 60; t += 2) {
            d.summary(summary(t, ON_THE_SIDE, 15, 1020)).ifPresent(falls::add);
        }
        assertEquals(1, falls.size(), "a node that never saw its wearer walk judges as before: " + falls);
    }

    @Test
    void anUprightKnownFromBeforeCountsAtOnce() {
        FallDetector d = new FallDetector(FallDetectorTest.SETTINGS, UPRIGHT);
        for (int t = 12; t <= 30; t += 2) {
            d.summary(summary(t, LYING, 15, 1020)).ifPresent(falls::add);
        }
        d.burst(burst(30.5, LYING, 2600, ON_THE_SIDE)).ifPresent(falls::add);
        for (int t = 34; t <= 60; t += 2) {
            d.summary(summary(t, ON_THE_SIDE, 15, 1020)).ifPresent(falls::add);
        }
        assertEquals(List.of(), falls, "the upright known from before: the turn is no fall without a walk first");
    }
}

package org.tinysep.falldetection.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.falldetection.internal.Nodes.LYING;
import static org.tinysep.falldetection.internal.Nodes.T0;
import static org.tinysep.falldetection.internal.Nodes.UPRIGHT;
import static org.tinysep.falldetection.internal.Nodes.burst;
import static org.tinysep.falldetection.internal.Nodes.summary;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;

class FallDetectorTest {

    /** Fixed here rather than the defaults, which leave-one-subject-out may change. */
    static final FallSettings SETTINGS = new FallSettings(2000, 45, 100, Duration.ofSeconds(4),
            Duration.ofSeconds(20));
    private final FallDetector detector = new FallDetector(SETTINGS);
    private final List<Fall> falls = new ArrayList<>();

    /** Walking until 10 s, a burst triggered at 10.5 s, then the summaries from 12 s on say {@code after}. */
    private void play(int peakMg, Acceleration after, int sdAfter) {
        for (int t = 2; t <= 10; t += 2) {
            detector.summary(summary(t, UPRIGHT, 250, 1600)).ifPresent(falls::add);
        }
        detector.summary(summary(12, new Acceleration(300, -500, 500), 900, peakMg)).ifPresent(falls::add);
        detector.burst(burst(10.5, UPRIGHT, peakMg, after)).ifPresent(falls::add); // complete 2 s after the trigger
        for (int t = 14; t <= 40; t += 2) {
            detector.summary(summary(t, after, sdAfter, 1000 + sdAfter)).ifPresent(falls::add);
        }
    }

    @Test
    void anImpactThenLyingStillIsAFall() {
        play(3100, LYING, 20);
        assertEquals(1, falls.size(), "one fall, alerted once");
        Fall f = falls.get(0);
        assertEquals(T0.plusMillis(10_520), f.impact(), "the impact is the burst's highest sample");
        assertEquals(3100, f.peakMg(), 2);
        assertTrue(f.angleDeg() > 80, "upright to lying: " + f.angleDeg());
        assertEquals(T0.plusSeconds(16), f.detectedAt(), "the first 4 s of stillness that began after the impact");
        assertEquals(Duration.ofSeconds(4), f.still());
    }

    @Test
    void aSoftLandingIsNotAnImpact() {
        play(1900, LYING, 20);
        assertEquals(List.of(), falls);
    }

    @Test
    void standingStillAfterAnImpactIsNotAFall() {
        play(3500, UPRIGHT, 20); // a jump, a stamp: hard, but the posture did not change
        assertEquals(List.of(), falls);
    }

    @Test
    void movingOnAfterAnImpactIsNotAFall() {
        play(3500, LYING, 400); // rolled over and got up again: never still
        assertEquals(List.of(), falls);
    }

    @Test
    void stillnessThatBeginsTooLateDoesNotCount() {
        for (int t = 2; t <= 10; t += 2) {
            detector.summary(summary(t, UPRIGHT, 250, 1600));
        }
        detector.burst(burst(10.5, UPRIGHT, 3000, LYING));
        Optional<Fall> f = Optional.empty();
        for (int t = 12; t <= 60; t += 2) {
            Optional<Fall> now = detector.summary(summary(t, t < 34 ? UPRIGHT : LYING, t < 34 ? 300 : 10, 1500));
            if (now.isPresent()) {
                f = now;
            }
        }
        assertTrue(f.isEmpty(), "stillness from 32 s on is more than 20 s after the impact");
    }

    /**
     * As the platform delivers them: every report stamped with the whole second it arrived in. The summary stamped
     * 7 s really ended at 7.98 s and holds the fall; the one stamped 9 s really began after the impact.
     */
    @Test
    void wholeSecondStampsNeitherHideThePostureBeforeNorDelayTheStillness() {
        for (int t = 1; t <= 5; t += 2) {
            detector.summary(summary(t, UPRIGHT, 250, 1600)).ifPresent(falls::add);
        }
        detector.summary(summary(7, new Acceleration(20, -300, 800), 1052, 6000)).ifPresent(falls::add);
        detector.burst(burst(7, UPRIGHT, 3000, LYING)).ifPresent(falls::add); // chunk 0 arrived in second 7
        for (int t = 9; t <= 21; t += 2) {
            detector.summary(summary(t, LYING, 5, 1010)).ifPresent(falls::add);
        }
        assertEquals(1, falls.size(), "a fall: " + falls);
        assertTrue(falls.get(0).angleDeg() > 80, "the posture before is the upright one: " + falls.get(0));
        assertEquals(T0.plusSeconds(11), falls.get(0).detectedAt(), "stillness from the summary stamped 9 s on");
    }

    @Test
    void aBurstNoAccelerometerCouldSendIsRefused() {
        List<Acceleration> s = new ArrayList<>(burst(1, UPRIGHT, 3000, LYING).samples());
        s.set(60, new Acceleration(40_000, 0, 0));
        AccelerationBurst bad = new AccelerationBurst(T0, 50, 50, s);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> detector.burst(bad));
        assertTrue(e.getMessage().contains("40000 mg"), e.getMessage());
        AccelerationBurst slow = new AccelerationBurst(T0, 1, 50, s.subList(0, 100));
        assertThrows(IllegalArgumentException.class, () -> detector.burst(slow));
    }

    @Test
    void angles() {
        assertEquals(90, FallDetector.angle(new Acceleration(0, -1000, 0), new Acceleration(0, 0, 1000)), 1e-9);
        assertEquals(0, FallDetector.angle(new Acceleration(0, -1000, 0), new Acceleration(0, -500, 0)), 1e-9);
        assertEquals(0, FallDetector.angle(new Acceleration(0, 0, 0), new Acceleration(0, -500, 0)), 1e-9);
    }

    @Test
    void settingsOutOfRangeAreSaidInWords() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new FallSettings(0, 45, 100, Duration.ofSeconds(4), Duration.ofSeconds(20)));
        assertTrue(e.getMessage().contains("impact 0 mg"), e.getMessage());
    }
}

package org.tinysep.falldetection.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.MovementSummary;

/** Recorded-like windows for the tests: what a node sends while upright, walking, falling, lying. */
final class Nodes {

    static final Instant T0 = Instant.parse("2026-03-02T14:00:00Z");
    static final Acceleration UPRIGHT = new Acceleration(0, -1000, 0);
    static final Acceleration LYING = new Acceleration(30, -80, 995);

    private Nodes() {
    }

    /** A 2 s summary ending {@code endS} seconds after T0. */
    static MovementSummary summary(double endS, Acceleration mean, int sdMg, int peakMg) {
        return new MovementSummary(T0.plusMillis(Math.round(endS * 1000)), Duration.ofSeconds(2), mean, sdMg,
                peakMg);
    }

    /** A 50 Hz burst triggered at {@code triggerS}: 50 samples of {@code before}, a peak, then {@code after}. */
    static AccelerationBurst burst(double triggerS, Acceleration before, int peakMg, Acceleration after) {
        List<Acceleration> s = new ArrayList<>();
        for (int i = 0; i < 50; i++) {
            s.add(before);
        }
        s.add(new Acceleration(0, -1800, 0)); // the trigger sample
        s.add(new Acceleration(peakMg / 2, -peakMg * 866 / 1000, 0)); // the impact, 20 ms later
        for (int i = 0; i < 98; i++) {
            s.add(after);
        }
        return new AccelerationBurst(T0.plusMillis(Math.round(triggerS * 1000)), 50, 50, s);
    }
}

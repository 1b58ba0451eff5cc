package org.tinysep.evaluation.falls;

import java.io.PrintStream;
import java.time.Duration;
import java.time.Instant;
import java.util.Locale;
import org.tinysep.falldetection.internal.FallSettings;

/**
 * {@code --why}: for each missed fall, which single setting, relaxed, would have alerted; for each false alert,
 * when it came and which setting, tightened, would have kept it quiet. The reference is the settings each
 * recording was judged with (its fold's under leave-one-subject-out).
 */
final class Why {

    private Why() {
    }

    static void print(PrintStream out, java.util.List<Scored> scored,
            java.util.function.Function<String, FallSettings> settings) {
        out.println("Why (relative to the settings each recording was judged with):");
        for (Scored s : scored) {
            String name = s.stream().recording().name();
            FallSettings d = settings.apply(s.stream().recording().subject());
            if (s.fall() && s.delay().isEmpty()) {
                out.println("- missed " + name + ": " + missReason(s, d)
                        + (s.alerts().isEmpty() ? "" : "; alerts outside the 30 s window at "
                                + offsets(s.alerts(), s.stream().impact())));
            } else if (!s.fall() && !s.alerts().isEmpty()) {
                out.println("- false alert " + name + " at " + offsets(s.alerts(), NodeStream.T0)
                        + " after its start: " + alertReason(s, d));
            }
        }
    }

    private static String missReason(Scored s, FallSettings d) {
        if (alerts(s, d)) {
            return "the detector alerts on it in process with these settings: lost only through the platform "
                    + "(frames stamped later than played, or a frame that did not arrive: see the run's 'stamped later' line)";
        }
        if (alerts(s, d.withImpactMg(1))) {
            return "no impact reached " + d.impactMg() + " mg (or no burst was sent)";
        }
        if (alerts(s, d.withAlreadyLyingDeg(180))) {
            return "the posture before the impact was " + Math.round(d.alreadyLyingDeg()) + "° or more from the "
                    + "wearer's learned upright (taken for already lying)";
        }
        if (alerts(s, d.withPostureChangeDeg(0))) {
            return "the posture changed less than " + Math.round(d.postureChangeDeg()) + "°";
        }
        if (alerts(s, d.withStillSdMg(100_000))) {
            return "never still (SD ≤ " + d.stillSdMg() + " mg) for " + d.stillFor().toSeconds() + " s";
        }
        return "only several settings relaxed together would alert";
    }

    private static String alertReason(Scored s, FallSettings d) {
        if (!alerts(s, d)) {
            return "only through the platform: the detector in process is quiet with these settings";
        }
        for (int impact : new int[] {2500, 3000, 4000}) {
            if (!alerts(s, d.withImpactMg(impact))) {
                return "peak below " + impact + " mg";
            }
        }
        for (int deg : new int[] {60, 75}) {
            if (!alerts(s, d.withPostureChangeDeg(deg))) {
                return "posture change below " + deg + "°";
            }
        }
        if (!alerts(s, d.withStillFor(Duration.ofSeconds(8)))) {
            return "still for less than 8 s";
        }
        return "a hard impact, a new posture and stillness, as in a fall";
    }

    private static boolean alerts(Scored s, FallSettings f) {
        Scored x = Scored.run(s.stream(), f, s.upright());
        return s.fall() ? x.delay().isPresent() : !x.alerts().isEmpty();
    }

    private static String offsets(java.util.List<Instant> at, Instant from) {
        StringBuilder b = new StringBuilder();
        for (Instant i : at) {
            b.append(b.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%+.1f s",
                    Duration.between(from, i).toMillis() / 1000.0));
        }
        return b.toString();
    }
}

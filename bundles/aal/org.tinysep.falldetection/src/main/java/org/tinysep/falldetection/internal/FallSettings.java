package org.tinysep.falldetection.internal;

import java.time.Duration;
import java.util.Objects;

/**
 * The detector's thresholds (README "Algorithm").
 *
 * @param impactMg        a burst whose peak magnitude reaches this is an impact, milli-g
 * @param postureChangeDeg the mean vector of the still period must differ from the one before the impact by this
 * @param stillSdMg       a movement summary whose magnitude SD is at most this counts as still, milli-g
 * @param stillFor        how long the person must stay still (consecutive still summaries)
 * @param within          the stillness must begin within this time after the impact
 * @param alreadyLyingDeg an impact whose posture before is at least this far from the wearer's learned upright is
 *                        not a fall: the person was already lying (turning over, getting up); 180 switches it off
 */
public record FallSettings(int impactMg, double postureChangeDeg, int stillSdMg, Duration stillFor,
        Duration within, double alreadyLyingDeg) {

    /**
     * The defaults: the settings leave-one-subject-out chose in every fold on SisFall since session 31 (four of five
     * before; docs/fall-detection.md); its figures are those of the folds, not of these settings on all subjects.
     * Six seconds of stillness, not four: a deliberate lie-down keeps still for about four.
     */
    public static final FallSettings DEFAULT = new FallSettings(2000, 30, 50, Duration.ofSeconds(6),
            Duration.ofSeconds(20), 70);

    /** These thresholds with the already-lying rule at its default. */
    public FallSettings(int impactMg, double postureChangeDeg, int stillSdMg, Duration stillFor, Duration within) {
        this(impactMg, postureChangeDeg, stillSdMg, stillFor, within, 70);
    }

    public FallSettings {
        Objects.requireNonNull(stillFor, "stillFor");
        Objects.requireNonNull(within, "within");
        if (impactMg <= 0 || postureChangeDeg < 0 || postureChangeDeg > 180 || stillSdMg < 0
                || stillFor.isNegative() || stillFor.isZero() || within.isNegative() || within.isZero()
                || !(alreadyLyingDeg >= 0 && alreadyLyingDeg <= 180)) {
            throw new IllegalArgumentException("fall detection settings out of range: impact " + impactMg
                    + " mg (> 0), posture change " + postureChangeDeg + "° (0..180), still SD " + stillSdMg
                    + " mg (>= 0), still for " + stillFor.toSeconds() + " s (> 0), within " + within.toSeconds()
                    + " s (> 0), already lying from " + alreadyLyingDeg + "° (0..180)");
        }
    }

    /** @return these settings from the bundle's configuration */
    static FallSettings of(FallDetectionConfig c) {
        return new FallSettings(c.impactMg(), c.postureChangeDegrees(), c.stillSdMg(),
                Duration.ofSeconds(c.stillSeconds()), Duration.ofSeconds(c.withinSeconds()), c.alreadyLyingDegrees());
    }

    public FallSettings withImpactMg(int v) {
        return new FallSettings(v, postureChangeDeg, stillSdMg, stillFor, within, alreadyLyingDeg);
    }

    public FallSettings withPostureChangeDeg(double v) {
        return new FallSettings(impactMg, v, stillSdMg, stillFor, within, alreadyLyingDeg);
    }

    public FallSettings withStillSdMg(int v) {
        return new FallSettings(impactMg, postureChangeDeg, v, stillFor, within, alreadyLyingDeg);
    }

    public FallSettings withStillFor(Duration v) {
        return new FallSettings(impactMg, postureChangeDeg, stillSdMg, v, within, alreadyLyingDeg);
    }

    public FallSettings withAlreadyLyingDeg(double v) {
        return new FallSettings(impactMg, postureChangeDeg, stillSdMg, stillFor, within, v);
    }
}

package org.tinysep.inactivity.internal.learn;

import java.time.Duration;

/**
 * How limits are learned from quiet periods.
 *
 * @param minDays     a time window needs quiet periods on at least this many different days before its limit is
 *                    learned (before: the fixed limit, "cold start")
 * @param historyDays how many days of history are kept and learned from
 * @param margin      the learned limit is the usual maximum times this factor ...
 * @param pad         ... plus this
 * @param floor       a learned limit is never shorter
 * @param ceiling     nor longer (a collapse must be reported within this)
 * @param halfWindow  quiet periods that began this many hours before or after the hour asked for count too
 * @param minPeriodsToShorten "never worse than the fixed limits": a learned limit may be shorter than
 *                    the room's fixed limit only when at least this many observed quiet periods support it; with
 *                    thinner history the fixed (thesis) limit holds. A longer learned limit needs no such support.
 * @param residents   the home's residents as the installer declares them, or 0: recognised from the history
 *                    ({@link TwoAtOnce}); with several, a learned limit is never longer than the fixed one and an
 *                    activity where a mat is ON is a resting person's ({@link Residents}). The constructors without
 *                    it declare 1; a learned profile's settings carry the count in effect (1, or 2 and more)
 */
public record LearningSettings(int minDays, int historyDays, double margin, Duration pad, Duration floor,
        Duration ceiling, int halfWindow, int minPeriodsToShorten, int residents) {

    /** The default of {@link #minPeriodsToShorten()}. */
    public static final int MIN_PERIODS_TO_SHORTEN = 30;

    /** One resident. */
    public LearningSettings(int minDays, int historyDays, double margin, Duration pad, Duration floor,
            Duration ceiling, int halfWindow, int minPeriodsToShorten) {
        this(minDays, historyDays, margin, pad, floor, ceiling, halfWindow, minPeriodsToShorten, 1);
    }

    /** With the default {@link #MIN_PERIODS_TO_SHORTEN}. */
    public LearningSettings(int minDays, int historyDays, double margin, Duration pad, Duration floor,
            Duration ceiling, int halfWindow) {
        this(minDays, historyDays, margin, pad, floor, ceiling, halfWindow, MIN_PERIODS_TO_SHORTEN);
    }

    /** The defaults documented in the bundle README (the residents recognised from the history). */
    public static LearningSettings defaults() {
        return new LearningSettings(7, 28, 1.5, Duration.ofMinutes(10), Duration.ofMinutes(20),
                Duration.ofHours(12), 1).withResidents(0);
    }

    /** @return these settings with another {@link #minPeriodsToShorten()} (0: any history may shorten a limit) */
    public LearningSettings withMinPeriodsToShorten(int n) {
        return new LearningSettings(minDays, historyDays, margin, pad, floor, ceiling, halfWindow, n, residents);
    }

    /** @return these settings for a home of {@code n} residents (0: recognised from the history) */
    public LearningSettings withResidents(int n) {
        return new LearningSettings(minDays, historyDays, margin, pad, floor, ceiling, halfWindow, minPeriodsToShorten,
                n);
    }

    /** @return these settings with another {@link #margin()} (the day-by-day margin check's, {@code MarginCheck}) */
    public LearningSettings withMargin(double m) {
        return new LearningSettings(minDays, historyDays, m, pad, floor, ceiling, halfWindow, minPeriodsToShorten,
                residents);
    }

    public LearningSettings {
        if (minDays < 1 || historyDays < minDays || margin < 1 || pad.isNegative() || floor.isNegative()
                || ceiling.compareTo(floor) < 0 || halfWindow < 0 || halfWindow > 11 || minPeriodsToShorten < 0
                || residents < 0) {
            throw new IllegalArgumentException("inconsistent learning settings: minDays " + minDays
                    + ", historyDays " + historyDays + ", margin " + margin + ", pad " + pad + ", floor " + floor
                    + ", ceiling " + ceiling + ", halfWindow " + halfWindow + ", minPeriodsToShorten "
                    + minPeriodsToShorten + ", residents " + residents);
        }
    }
}

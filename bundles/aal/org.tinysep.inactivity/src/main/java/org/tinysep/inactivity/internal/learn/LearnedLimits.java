package org.tinysep.inactivity.internal.learn;

import java.time.Duration;
import java.time.Instant;

/**
 * The LEARNED detector's limit for a quiet period: the learned one where the history suffices, else the fixed
 * (thesis) limit of the room, never below the floor. Pure Java: the platform's device and an evaluation harness
 * call it alike.
 * <p>
 * Cold start without a switch: with history on n days, 1 ≤ n < {@code minDays}, for the room and state
 * (at any time of day), the limit is a credibility-weighted mean of what those days taught (L) and the fixed limit
 * (F): Z·L + (1 − Z)·F with Z = √(n / minDays) — the square-root rule of limited-fluctuation credibility (an
 * estimate from n observations gets full weight once n reaches the standard for full credibility, here
 * {@code minDays}). So the first day of history already moves the limit a little, and the change at
 * {@code minDays} is small instead of a switch from the thesis's limit to the learned one.
 */
public final class LearnedLimits {

    private final HistoryLearner history;

    public LearnedLimits(HistoryLearner history) {
        this.history = history;
    }

    /**
     * @param s     the sighting that begins the quiet period (it is also learned from)
     * @param fixed the room's fixed limit (cold start), e.g. 45 min for a bathroom
     * @param now   the platform's time
     */
    public Limit limitAfter(Sighting s, Duration fixed, Instant now) {
        history.add(s);
        history.fixedLimit(s.room(), fixed);
        boolean asleep = history.sleep().asleep(s);
        QuietProfile profile = history.profile(now);
        LearningSettings set = profile.settings();
        boolean seated = s.seated() && !asleep;
        return profile.learned(s.room(), s.roomName(), asleep, seated, s.upFromBed(), s.at())
                .map(l -> neverWorse(s, l, new Limit(l.limit(), asleep, l.explain(set) + profile.marginWords()),
                        fixed, set, history.residents()))
                .orElseGet(() -> profile.partial(s.room(), s.roomName(), asleep, seated, s.upFromBed(), now)
                        .map(l -> neverWorse(s, l, blend(s, l, fixed, asleep, set), fixed, set, history.residents()))
                        .orElseGet(() -> coldStart(s, fixed, asleep, set)));
    }

    /**
     * "Never worse than the fixed limits", both ways. Shorter: a limit shorter than the fixed one needs
     * at least {@code minPeriodsToShorten} observed quiet periods behind it; with fewer the fixed limit holds (a
     * short limit learned from a handful of periods is what raised the learned detector's false alarms). Longer: a
     * limit longer than the fixed one must be learned from the hours it is used at; learned from the room's whole
     * day (those hours had quiet periods on too few days, or it is a cold start's blend) the fixed limit holds (a
     * long afternoon sit lengthened the evening's limit to hours and was what made the learned detector slow); and
     * in a home of several residents ({@link Residents}) a learned limit is never longer than the fixed one.
     */
    static Limit neverWorse(Sighting s, Learned l, Limit learned, Duration fixed, LearningSettings set,
            Residents residents) {
        int longer = learned.limit().compareTo(fixed);
        if (decide(l, learned.limit(), fixed, set).equals(learned.limit())) {
            return learned;
        }
        if (longer > 0 && set.residents() > 1) {
            return new Limit(fixed, learned.asleep(), "fixed limit of " + Amounts.duration(fixed) + " for "
                    + s.roomName() + (learned.asleep() ? " asleep" : "") + ": the history would lengthen it to "
                    + Amounts.duration(learned.limit()) + ", but " + residents.words() + ": a collapse is found only "
                    + "once the others are quiet too, so a learned limit is never longer than the fixed one ("
                    + l.explain(set) + ")");
        }
        if (longer > 0) {
            return new Limit(fixed, learned.asleep(), "fixed limit of " + Amounts.duration(fixed) + " for "
                    + s.roomName() + (learned.asleep() ? " asleep" : "") + ": the history would lengthen it to "
                    + Amounts.duration(learned.limit()) + ", but only from other hours of the day (at these hours "
                    + "there are quiet periods on fewer than " + Amounts.count(set.minDays(), "day")
                    + "), and a longer limit must be learned from the hours it is used at (" + l.explain(set) + ")");
        }
        return new Limit(fixed, learned.asleep(), "fixed limit of " + Amounts.duration(fixed) + " for "
                + s.roomName() + (learned.asleep() ? " asleep" : "") + ": the history would shorten it to "
                + Amounts.duration(learned.limit()) + ", but only " + Amounts.count(l.periods(), "quiet period")
                + " support that and a shorter limit needs at least " + set.minPeriodsToShorten()
                + " (" + l.explain(set) + ")");
    }

    /**
     * The rule of {@link #neverWorse} without its words (the day-by-day margin check, {@link MarginCheck}, asks it
     * for every past quiet period).
     *
     * @return {@code learned}, or {@code fixed} where the rule keeps the fixed limit
     */
    static Duration decide(Learned l, Duration learned, Duration fixed, LearningSettings set) {
        int longer = learned.compareTo(fixed);
        if (longer > 0 && (l.allDay() || set.residents() > 1)) {
            return fixed;
        }
        return longer >= 0 || l.periods() >= set.minPeriodsToShorten() ? learned : fixed;
    }

    /** Fewer than minDays days: Z·learned + (1 − Z)·fixed, Z = √(days / minDays); never below the floor. */
    static Limit blend(Sighting s, Learned l, Duration fixed, boolean asleep, LearningSettings set) {
        double z = Math.sqrt((double) l.days() / set.minDays());
        long secs = Math.round(z * l.limit().getSeconds() + (1 - z) * fixed.getSeconds());
        Duration d = Duration.ofSeconds(Math.max(secs, set.floor().getSeconds()));
        return new Limit(d, asleep, "limit " + Amounts.duration(d) + " = " + Math.round(100 * z) + " % of what "
                + Amounts.count(l.days(), "day") + " of history taught (" + l.explain(set) + ") and "
                + Math.round(100 * (1 - z)) + " % of the fixed limit of " + Amounts.duration(fixed) + " for "
                + s.roomName() + (asleep ? " asleep" : "") + ": fewer than " + Amounts.count(set.minDays(), "day")
                + " of history yet, so the fixed limit still counts (weight of the history = square root of "
                + l.days() + "/" + set.minDays() + ")");
    }

    private Limit coldStart(Sighting s, Duration fixed, boolean asleep, LearningSettings set) {
        Duration d = fixed;
        return new Limit(d, asleep, "fixed limit of " + Amounts.duration(d) + " for " + s.roomName()
                + (asleep ? " asleep" : "") + ": fewer than " + Amounts.count(set.minDays(), "day") + " of history for this room"
                + (asleep ? " asleep" : "") + " yet, so nothing is learned");
    }

    public HistoryLearner history() {
        return history;
    }

    /**
     * @return the home's residents and its mats now ON: the platform reads each sighting through it first (the first
     *         activity after a start too, before any learning: with what the history shows, not as one resident's)
     */
    public Residents residents() {
        return history.residents();
    }
}

package org.tinysep.inactivity.internal.learn;

import java.time.Duration;
import java.time.Instant;

/**
 * The LEARNED detector's limit for a quiet period: the learned one where the history suffices, else the fixed
 * (thesis) limit of the room, never below the floor. Pure Java: the platform's device and an evaluation harness
 * call it alike.
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
        boolean asleep = history.sleep().asleep(s);
        LearningSettings set = history.settings();
        return history.profile(now).learned(s.room(), s.roomName(), asleep, s.at())
                .map(l -> new Limit(l.limit(), asleep, l.explain(set)))
                .orElseGet(() -> coldStart(s, fixed, asleep, set));
    }

    private Limit coldStart(Sighting s, Duration fixed, boolean asleep, LearningSettings set) {
        Duration d = fixed;
        return new Limit(d, asleep, "fixed limit of " + Words.duration(d) + " for " + s.roomName()
                + (asleep ? " asleep" : "") + ": fewer than " + Words.count(set.minDays(), "day") + " of history for this room"
                + (asleep ? " asleep" : "") + " yet, so nothing is learned");
    }

    public HistoryLearner history() {
        return history;
    }
}

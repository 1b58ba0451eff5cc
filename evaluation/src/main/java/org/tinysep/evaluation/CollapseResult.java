package org.tinysep.evaluation;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.List;

/**
 * The outcome of one injected collapse.
 *
 * @param at      the collapse (recorded time)
 * @param quietSince the last kept event before it: the quiet period runs from here
 * @param outcome DETECTED (alerted within 12 h), ALREADY_ALERTED (an alert raised in the same quiet period before the
 *                collapse: not detected), MISSED
 * @param delay   from the collapse to the alert, for DETECTED
 */
record CollapseResult(LocalDateTime at, LocalDateTime quietSince, Outcome outcome, Duration delay) {

    static final Duration WINDOW = Duration.ofHours(12);

    enum Outcome { DETECTED, ALREADY_ALERTED, MISSED }

    static CollapseResult judge(LocalDateTime at, LocalDateTime quietSince, List<LocalDateTime> alerts) {
        for (LocalDateTime a : alerts) {
            if (!a.isBefore(quietSince) && !a.isAfter(at)) {
                return new CollapseResult(at, quietSince, Outcome.ALREADY_ALERTED, null);
            }
        }
        for (LocalDateTime a : alerts) {
            if (a.isAfter(at) && !a.isAfter(at.plus(WINDOW))) {
                return new CollapseResult(at, quietSince, Outcome.DETECTED, Duration.between(at, a));
            }
        }
        return new CollapseResult(at, quietSince, Outcome.MISSED, null);
    }
}

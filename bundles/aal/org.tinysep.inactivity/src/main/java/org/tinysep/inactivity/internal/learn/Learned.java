package org.tinysep.inactivity.internal.learn;

import java.time.Duration;

/**
 * A limit learned for one room, state and time of day, with how it was learned.
 *
 * @param roomName  the room's name
 * @param asleep    whether it is the sleep state's limit
 * @param scope     the time window in words, e.g. "between 13:00 and 16:00 on weekdays", "at any time of day"
 * @param usual     the usual longest quiet period there (see {@link UsualQuiet})
 * @param limit     the limit that follows from it
 * @param days      how many days of history it was learned from
 * @param periods   how many quiet periods those days held
 * @param allDay    true when it was learned from the room's whole day because the hours asked about had quiet
 *                  periods on too few days (a limit longer than the fixed one is then not used)
 */
public record Learned(String roomName, boolean asleep, String scope, Duration usual, Duration limit, int days,
        int periods, boolean allDay) {

    /**
     * @return e.g. "usually at most 40 min between 13:00 and 16:00 in Bathroom, from 21 days (63 quiet periods);
     *         limit 1 h 10 min = usual x 1.5 + 10 min, at least 20 min"
     */
    public String explain(LearningSettings s) {
        return "usually at most " + Amounts.duration(usual) + " " + scope + (asleep ? " asleep" : "") + " in "
                + roomName + ", from " + Amounts.count(days, "day") + " (" + Amounts.count(periods, "quiet period") + "); limit "
                + Amounts.duration(limit) + " = usual x " + Amounts.factor(s.margin()) + " + " + Amounts.duration(s.pad())
                + ", at least " + Amounts.duration(s.floor());
    }
}

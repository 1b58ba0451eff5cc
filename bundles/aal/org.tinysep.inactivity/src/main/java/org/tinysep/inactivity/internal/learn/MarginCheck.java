package org.tinysep.inactivity.internal.learn;

import java.time.Duration;
import java.time.LocalDate;
import java.time.ZoneId;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.function.Function;

/**
 * "Never worse than the fixed limits", checked on the home's own past days (issue 28). Each past day's quiet
 * periods are judged with limits learned from the days before it only, as the detector met that day (a forward,
 * day-by-day check: the day is held out of what it is judged with, and so are the days after it, which the
 * detector could not have known); a period that outlasted its limit is an alarm the learned detector would have
 * raised on that day. The fixed limits' alarms on the same periods are counted too. The learned limits use the
 * smallest margin, from the configured one up to twice it in steps of {@link #STEP}, at which they would have raised
 * no more alarms than the fixed limits; if none does, twice the configured margin. Where the history is regular the
 * configured margin stands; where quiet periods often outlasted what the days before had taught, the learned limits
 * get longer until they would have raised no more alarms than the fixed ones. Only the margin is chosen so: which
 * room, state and hours a limit is learned from, and the rules of {@link LearnedLimits#neverWorse}, are unchanged.
 */
final class MarginCheck {

    /** The margins tried: the configured one, then this much more each time, up to twice it. */
    static final double STEP = 0.25;

    /**
     * What the check found.
     *
     * @param margin        the margin the learned limits use
     * @param base          the configured margin
     * @param baseAlarms    alarms the learned limits with the configured margin would have raised on the past days
     *                      (each day judged with what the days before it taught)
     * @param fixedAlarms   alarms the fixed limits would have raised on the same quiet periods
     * @param days          how many past days were judged
     */
    record Result(double margin, double base, int baseAlarms, int fixedAlarms, int days) {

        static Result unchecked(double base) {
            return new Result(base, base, 0, 0, 0);
        }

        /** @return empty when the configured margin stands, else why the margin is larger, in plain words */
        String words() {
            if (margin == base) {
                return "";
            }
            return "; x " + Amounts.factor(margin) + " rather than x " + Amounts.factor(base) + " because over the last "
                    + Amounts.count(days, "day") + ", each day judged with what the days before it taught, x "
                    + Amounts.factor(base) + " would have called for help " + Amounts.count(baseAlarms, "time")
                    + " where the fixed limits called " + Amounts.count(fixedAlarms, "time");
        }
    }

    private MarginCheck() {
    }

    /**
     * @param gaps  the history's quiet periods
     * @param fixed each room's fixed limit (null: unknown, its periods are not judged)
     */
    static Result choose(List<Gap> gaps, ZoneId zone, LearningSettings set, Function<String, Duration> fixed) {
        Map<LocalDate, List<Gap>> byDay = new TreeMap<>();
        List<LocalDate> dates = new ArrayList<>(gaps.size());
        for (Gap g : gaps) {
            LocalDate d = g.start().at().atZone(zone).toLocalDate();
            dates.add(d);
            byDay.computeIfAbsent(d, k -> new ArrayList<>()).add(g);
        }
        if (byDay.size() <= set.minDays()) {
            return Result.unchecked(set.margin()); // no past day had enough days before it to learn from
        }
        int steps = (int) Math.round(set.margin() / STEP);
        double[] margins = new double[steps + 1];
        for (int i = 0; i <= steps; i++) {
            margins[i] = set.margin() + i * STEP;
        }
        int[] alarms = new int[margins.length];
        int fixedAlarms = 0;
        for (Map.Entry<LocalDate, List<Gap>> day : byDay.entrySet()) {
            List<Gap> before = new ArrayList<>(gaps.size());
            for (int k = 0; k < gaps.size(); k++) {
                if (dates.get(k).isBefore(day.getKey())) {
                    before.add(gaps.get(k));
                }
            }
            QuietProfile without = new QuietProfile(before, zone, set);
            for (Gap g : day.getValue()) {
                Duration f = fixed.apply(g.start().room());
                if (f == null) {
                    continue;
                }
                fixedAlarms += g.length().compareTo(f) > 0 ? 1 : 0;
                Optional<Learned> l = without.learned(g.start().room(), g.start().roomName(), g.asleep(),
                        g.start().seated(), g.start().upFromBed(), g.start().at());
                for (int i = 0; i < margins.length; i++) {
                    Duration limit = l.isEmpty() ? f : LearnedLimits.decide(l.get(),
                            UsualQuiet.limit(l.get().usual(), set.withMargin(margins[i])), f, set);
                    alarms[i] += g.length().compareTo(limit) > 0 ? 1 : 0;
                }
            }
        }
        int chosen = margins.length - 1;
        for (int i = 0; i < margins.length; i++) {
            if (alarms[i] <= fixedAlarms) {
                chosen = i;
                break;
            }
        }
        return new Result(margins[chosen], set.margin(), alarms[0], fixedAlarms, byDay.size());
    }
}

package org.tinysep.inactivity.internal.learn;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * The statistic of one time window: from the longest quiet period of each day (the "daily maximum", as Cuddihy
 * et al. 2007 learn the maximum inactivity per hour), the usual maximum is the largest daily maximum, but no more
 * than Tukey's far-out fence (Q3 + 3 IQR) of the daily maxima once there are 7 days or more: one freak period (an
 * outage, an absence the door did not see) cannot lift a limit by hours. The limit is usual × margin + pad,
 * between floor and ceiling.
 */
final class UsualQuiet {

    private UsualQuiet() {
    }

    /** @param dailyMaxima the longest quiet period of each day, at least one */
    static Duration usual(List<Duration> dailyMaxima) {
        List<Duration> m = new ArrayList<>(dailyMaxima);
        Collections.sort(m);
        Duration max = m.get(m.size() - 1);
        if (m.size() < 7) {
            return max;
        }
        double q1 = quantile(m, 0.25);
        double q3 = quantile(m, 0.75);
        long fence = (long) Math.ceil(q3 + 3 * (q3 - q1));
        return max.getSeconds() > fence ? Duration.ofSeconds(fence) : max;
    }

    /** Linear interpolation between order statistics (seconds). */
    static double quantile(List<Duration> sorted, double p) {
        double pos = p * (sorted.size() - 1);
        int lo = (int) Math.floor(pos);
        int hi = Math.min(lo + 1, sorted.size() - 1);
        double f = pos - lo;
        return sorted.get(lo).getSeconds() * (1 - f) + sorted.get(hi).getSeconds() * f;
    }

    static Duration limit(Duration usual, LearningSettings s) {
        Duration l = Duration.ofSeconds(Math.round(usual.getSeconds() * s.margin())).plus(s.pad());
        if (l.compareTo(s.floor()) < 0) {
            return s.floor();
        }
        return l.compareTo(s.ceiling()) > 0 ? s.ceiling() : l;
    }
}

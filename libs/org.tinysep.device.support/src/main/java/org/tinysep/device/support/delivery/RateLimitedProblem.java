package org.tinysep.device.support.delivery;

import java.time.Instant;
import java.util.function.BiFunction;

/** Counts losses and says them at most once a minute: the first at once, later ones summed up */
public final class RateLimitedProblem {

    private long unreported;
    private Instant since;
    private long lastReport = System.nanoTime() - OrderedDelivery.REPORT_NANOS;

    /**
     * One more loss at {@code at}.
     *
     * @param words the text for (count since the last report, time of the first of them)
     * @return the text to say now, or null while the last report is less than a minute old
     */
    public synchronized String drop(Instant at, BiFunction<Long, Instant, String> words) {
        if (unreported++ == 0) {
            since = at;
        }
        long now = System.nanoTime();
        if (now - lastReport < OrderedDelivery.REPORT_NANOS) {
            return null;
        }
        lastReport = now;
        String text = words.apply(unreported, since);
        unreported = 0;
        return text;
    }

    /** @return whether a report may be said now (a minute since the last); counts it as said */
    public synchronized boolean mayReport() {
        long now = System.nanoTime();
        if (now - lastReport < OrderedDelivery.REPORT_NANOS) {
            return false;
        }
        lastReport = now;
        return true;
    }
}

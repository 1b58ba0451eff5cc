package org.tinysep.device.support.health;

import java.time.Duration;
import java.time.Instant;

/**
 * Damps a flapping node: one whose silences (gaps of at least its normal silence limit between
 * two frames, declared or not) come {@value #FLAP_LIMIT} or more times within {@link #WINDOW}, e.g. a change-only
 * sensor whose report interval the platform assumes wrongly, or a node at the edge of radio range. While it flaps its
 * silence limit is twice the longest of those silences (at least twice the normal limit), up to {@link #MAX_LIMIT}
 * (or the normal limit when that is longer): so a node that really reports every minute stops going OFFLINE/ONLINE
 * after {@value #FLAP_LIMIT} times; the limit is back to normal once fewer than {@value #FLAP_LIMIT} silences fall in
 * the last hour. No allocation per frame; not
 * thread-safe (guarded by its {@link NodeWatch}).
 */
final class FlapDamper {

    /** Silences within {@link #WINDOW} that make a node flapping. */
    static final int FLAP_LIMIT = 3;
    static final Duration WINDOW = Duration.ofHours(1);
    /** The longest widened silence limit. */
    static final Duration MAX_LIMIT = Duration.ofHours(1);
    private static final int KEPT = 16;

    private final long[] silences = new long[KEPT]; // when each ended, epoch millis; a ring
    private final long[] lengths = new long[KEPT]; // how long each lasted, millis
    private int next;
    private int size;
    private Instant noticed;

    /** A frame at {@code at} ended a gap of {@code millis}, at least the normal silence limit. */
    void silenceEnded(Instant at, long millis) {
        silences[next] = at.toEpochMilli();
        lengths[next] = millis;
        next = (next + 1) % KEPT;
        size = Math.min(KEPT, size + 1);
    }

    /**
     * @return true while the node flaps (its notice was written, its end not yet): then the widened limit and the
     *         notices move with time alone. Otherwise only a new silence ({@link #silenceEnded}) can start it.
     */
    boolean watching() {
        return noticed != null;
    }

    /** @return the silences in the hour before {@code now} (at most {@value #KEPT}) */
    int silences(Instant now) {
        int n = 0;
        for (int i = 0; i < size; i++) {
            n += inWindow(i, now) ? 1 : 0;
        }
        return n;
    }

    private boolean inWindow(int i, Instant now) {
        long to = now.toEpochMilli();
        return silences[i] > to - WINDOW.toMillis() && silences[i] <= to;
    }

    /** @return report intervals without a frame that make the node silent now: {@code configured}, or widened */
    int missed(int configured, Duration interval, Instant now) {
        if (silences(now) < FLAP_LIMIT) {
            return configured;
        }
        long step = interval.toMillis();
        long longest = 0;
        for (int i = 0; i < size; i++) {
            longest = inWindow(i, now) ? Math.max(longest, lengths[i]) : longest;
        }
        long most = Math.max(configured, (MAX_LIMIT.toMillis() + step - 1) / step);
        long widened = Math.max(2L * configured, (2 * longest + step - 1) / step);
        return (int) Math.min(most, widened);
    }

    /**
     * @return what to write in the event log on this tick: a notice when the node starts flapping, one summary an
     *         hour while it goes on, one line when it ends; else null
     */
    String notice(String node, int configured, Duration interval, Instant now) {
        int flaps = silences(now);
        Duration normal = interval.multipliedBy(configured);
        Duration widened = interval.multipliedBy(missed(configured, interval, now));
        boolean damped = widened.compareTo(normal) > 0;
        if (damped && noticed == null) {
            noticed = now;
            return HealthWords.flapping(node, flaps, normal, widened);
        }
        if (damped && !now.isBefore(noticed.plus(WINDOW))) {
            noticed = now;
            return HealthWords.stillFlapping(node, flaps, widened);
        }
        if (!damped && noticed != null) {
            noticed = null;
            return HealthWords.flappingEnded(node, normal);
        }
        return null;
    }
}

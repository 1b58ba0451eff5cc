package org.tinysep.device.support.health;

import java.time.Duration;
import java.time.Instant;

/**
 * One node's liveness in platform time (sensor health): when it was last heard, whether it has gone
 * silent (no valid frame for a configured number of its report intervals), how many frames it sent in the last
 * {@link #WINDOW} against how many its node types promise (link quality, thesis Table 5.4), and frames missing by
 * sequence number. Thread-safe; cheap on the packet path (no allocation per frame). An idle tick is cheap too:
 * {@link #due} says, without a lock or an allocation, whether {@link #checkSilence} and {@link #flapping} can have
 * anything to say now; a node that just reported is next due when its silence limit ends.
 */
public final class NodeWatch {

    /** The link-quality window: the thesis measured 5 minutes per position (5.2). */
    public static final Duration WINDOW = Duration.ofMinutes(5);
    private static final int BUCKETS = 30;
    private static final long BUCKET_SECONDS = WINDOW.getSeconds() / BUCKETS;

    private final long[] counts = new long[BUCKETS];
    private final long[] bucketOf = new long[BUCKETS];
    private Duration interval;
    private double perSecond;
    private Instant lastHeard;
    private Instant silenceBase;
    private Instant firstHeard;
    private Instant silentSince;
    private int lastSequence = -1;
    private long sequenceGaps;
    private long lastHeardNanos = System.nanoTime();
    private long realGuardNanos;
    private int configuredMissed;
    private final FlapDamper damper = new FlapDamper();
    /** Epoch millis from which the next tick's checks may say something; lowered by whatever brings it closer. */
    private volatile long dueMillis = Long.MIN_VALUE;
    /** The missed intervals {@link #dueMillis} was planned with, and the tick time it was planned at. */
    private volatile int dueFor = -1;
    private volatile long plannedAt = Long.MIN_VALUE;
    private volatile Runnable dueEarlier = () -> { };

    /**
     * @param interval  the node's report interval (silence is counted in these)
     * @param perSecond the reports per second the node promises (link quality)
     * @param lastHeard when it was last heard before (from a backup), or null
     */
    public NodeWatch(Duration interval, double perSecond, Instant lastHeard) {
        rates(interval, perSecond);
        this.lastHeard = lastHeard;
        this.silenceBase = lastHeard;
        java.util.Arrays.fill(bucketOf, Long.MIN_VALUE);
    }

    /**
     * Also requires this much real time without a frame before the node counts as silent. For links whose frames
     * are handled on their own receive thread rather than on the platform tick (serial, Sun SPOT): in lock-step
     * virtual time a day passes in seconds, and a receive thread lagging a fraction of a second behind the ticks
     * would otherwise make a node look silent for minutes of platform time. Default none.
     */
    public synchronized void realSilenceGuard(Duration guard) {
        this.realGuardNanos = guard.toNanos();
        earlier(Long.MIN_VALUE);
    }

    /** The node's types changed: new report interval and rate. */
    public synchronized void rates(Duration interval, double perSecond) {
        if (interval.isNegative() || interval.isZero()) {
            throw new IllegalArgumentException("report interval must be positive: " + interval);
        }
        this.interval = interval;
        this.perSecond = perSecond;
        earlier(Long.MIN_VALUE);
    }

    /**
     * A valid frame arrived.
     *
     * @param sequence the frame's sequence number 0..255, or -1 when the protocol has none
     * @return when the silence it ends began (the node was OFFLINE for silence), else null
     */
    public synchronized Instant heard(Instant at, int sequence) {
        if (firstHeard == null) {
            firstHeard = at;
        }
        long silence = lastHeard == null ? 0 : at.toEpochMilli() - lastHeard.toEpochMilli();
        if (configuredMissed > 0 && silence >= interval.toMillis() * configuredMissed) {
            damper.silenceEnded(at, silence); // a gap the normal limit counts as silence, declared or not (flapping)
            earlier(Long.MIN_VALUE); // it may start flapping
        }
        long limit = at.toEpochMilli() + interval.toMillis() * Math.max(1, configuredMissed);
        if (limit < dueMillis) {
            earlier(limit); // first heard, heard again after a silence, or heard with an earlier time stamp
        }
        lastHeard = at;
        silenceBase = at;
        lastHeardNanos = System.nanoTime();
        long bucket = Math.floorDiv(at.getEpochSecond(), BUCKET_SECONDS);
        int slot = (int) Math.floorMod(bucket, (long) BUCKETS);
        if (bucketOf[slot] != bucket) {
            bucketOf[slot] = bucket;
            counts[slot] = 0;
        }
        counts[slot]++;
        if (sequence >= 0) {
            if (lastSequence >= 0) {
                int gap = (sequence - lastSequence - 1) & 0xFF;
                if (gap < 128) { // a larger "gap" is a node restart or a frame out of order, not loss
                    sequenceGaps += gap;
                }
            }
            lastSequence = sequence;
        }
        Instant ended = silentSince;
        silentSince = null;
        return ended;
    }

    /**
     * Checks for silence on a platform tick. A flapping node's limit is widened ({@link #missedIntervals}).
     *
     * @param missedIntervals how many report intervals without a frame make the node silent
     * @return true when the node went silent just now (then {@link #silentSince()} is its last frame time)
     */
    public synchronized boolean checkSilence(Instant now, int missedIntervals) {
        configuredMissed = Math.max(1, missedIntervals);
        if (silentSince != null || silenceBase == null) {
            return false;
        }
        missedIntervals = damper.missed(configuredMissed, interval, now);
        if (now.isBefore(silenceBase)) { // the clock went back (end of a simulation): count from now
            silenceBase = now;
            return false;
        }
        if (Duration.between(silenceBase, now).compareTo(interval.multipliedBy(Math.max(1, missedIntervals))) < 0) {
            return false;
        }
        if (realGuardNanos > 0 && System.nanoTime() - lastHeardNanos < realGuardNanos) {
            return false; // the receive thread may only be behind the platform ticks
        }
        silentSince = lastHeard;
        return true;
    }

    /**
     * The node was re-created from a backup and has not been heard since the restart: silent since its last frame
     * before it ({@code lastHeard}, the epoch when unknown), without a new silence to report.
     */
    public synchronized void restored(Instant lastHeard) {
        this.lastHeard = lastHeard;
        this.silenceBase = lastHeard;
        this.silentSince = lastHeard == null ? Instant.EPOCH : lastHeard;
        earlier(Long.MIN_VALUE);
    }

    /**
     * Whether this tick's {@link #checkSilence} and {@link #flapping} can have anything to say: false for a node heard
     * within its silence limit, or silent (already declared) and not flapping. No lock, no allocation. Valid when each
     * tick that is due calls both; true when the clock went back or {@code missedIntervals} changed since.
     */
    public boolean due(Instant now, int missedIntervals) {
        long t = now.toEpochMilli();
        return t >= dueMillis || t < plannedAt || Math.max(1, missedIntervals) != dueFor;
    }

    /**
     * @param hook told (on the caller's thread, under this watch's lock: keep it short) whenever the next check
     *             comes closer than planned, e.g. the first frame, a frame after a silence, new report intervals; lets
     *             a node table skip a tick's look at all its nodes until the first of them is due
     */
    public void onDueEarlier(Runnable hook) {
        this.dueEarlier = hook;
    }

    /** @return epoch millis from which {@link #due} is true (planned by the last due tick; lowered since) */
    public long dueMillis() {
        return dueMillis;
    }

    private void earlier(long at) {
        dueMillis = at;
        dueEarlier.run();
    }

    /** After a tick's checks: when the next one can have something to say (guarded by this). */
    private void planNext(Instant now) {
        long t = now.toEpochMilli();
        long next;
        if (damper.watching()) {
            next = t + 1; // flapping: its hourly summary, its end and its widened limit move with time
        } else if (silentSince != null || silenceBase == null) {
            next = Long.MAX_VALUE; // silent or never heard: only a frame (heard) or a restore brings a check closer
        } else {
            long limit = silenceBase.toEpochMilli() + interval.toMillis() * configuredMissed;
            next = limit > t ? limit : t + 1; // past it: the real-time guard held the silence back, look again
        }
        plannedAt = t;
        dueFor = configuredMissed;
        dueMillis = next;
    }

    /**
     * @return the report intervals without a frame that make the node silent now: {@code configured}, or more
     *         while it flaps (went silent and came back {@value FlapDamper#FLAP_LIMIT} or more times within an hour:
     *         twice its longest such silence, at most an hour)
     */
    public synchronized int missedIntervals(int configured, Instant now) {
        return damper.missed(Math.max(1, configured), interval, now);
    }

    /**
     * Call on each platform tick after {@link #checkSilence}.
     *
     * @param node the node in words, e.g. {@code AmICA node 1.17 (Kitchen movement)}
     * @return the event-log text when the node starts flapping (begins {@code Monitoring reduced: }), an hourly
     *         summary while it goes on, or when it ends; else null
     */
    public synchronized String flapping(String node, Instant now) {
        if (configuredMissed == 0) {
            return null;
        }
        String notice = damper.notice(node, configuredMissed, interval, now);
        planNext(now);
        return notice;
    }

    public synchronized boolean silent() {
        return silentSince != null;
    }

    /** @return the last frame time before the current silence, null while heard */
    public synchronized Instant silentSince() {
        return silentSince;
    }

    public synchronized Instant lastHeard() {
        return lastHeard;
    }

    public synchronized Duration interval() {
        return interval;
    }

    public synchronized long sequenceGaps() {
        return sequenceGaps;
    }

    /** @return valid frames in the window ending now */
    public synchronized long received(Instant now) {
        long current = Math.floorDiv(now.getEpochSecond(), BUCKET_SECONDS);
        long sum = 0;
        for (int i = 0; i < BUCKETS; i++) {
            if (bucketOf[i] > current - BUCKETS && bucketOf[i] <= current) {
                sum += counts[i];
            }
        }
        return sum;
    }

    /** @return reports the node's types promise in the window ending now (since it was first heard) */
    public synchronized long expected(Instant now) {
        if (firstHeard == null) {
            return 0;
        }
        long current = Math.floorDiv(now.getEpochSecond(), BUCKET_SECONDS);
        Instant windowStart = Instant.ofEpochSecond((current - BUCKETS + 1) * BUCKET_SECONDS);
        boolean sinceFirst = !firstHeard.isBefore(windowStart);
        Instant from = sinceFirst ? firstHeard : windowStart;
        double seconds = Math.max(0, Duration.between(from, now).toMillis() / 1000.0);
        return (long) Math.floor(seconds * perSecond) + (sinceFirst ? 1 : 0);
    }

    /** @return "96 % (144 of 150 expected in the last 5 min)" or "not rated yet" */
    public String describeQuality(Instant now) {
        long expected = expected(now);
        long received = received(now);
        if (expected <= 1) {
            return "not rated yet";
        }
        long percent = Math.min(100, Math.round(100.0 * received / expected));
        return percent + " % (" + received + " of " + expected + " expected reports in the last "
                + WINDOW.toMinutes() + " min)";
    }
}

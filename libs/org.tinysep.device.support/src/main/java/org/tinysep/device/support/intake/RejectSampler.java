package org.tinysep.device.support.intake;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.LongSupplier;
import org.tinysep.api.log.Direction;
import org.tinysep.device.support.logs.Reporter;

/**
 * Keeps a flood of rejected input from wiping the packet-log history (a million invalid datagrams
 * would have rotated out weeks of real packets). Rejected frames go to the packet log in full while a budget lasts
 * ({@link #BURST} at once, refilled by {@link #PER_MINUTE} per minute of real time); beyond it they are only
 * counted, and at most once a minute one summary entry says how many were not kept and from where. The reject
 * counters themselves stay exact (the caller counts before it calls this). Thread-safe.
 */
public final class RejectSampler {

    /** Rejected frames kept in full in a burst. */
    public static final int BURST = 500;
    /** Rejected frames kept in full per minute once the burst is spent. */
    public static final int PER_MINUTE = 100;
    /** Most sources named in a summary; the rest are summed as "other sources". */
    static final int NAMED_SOURCES = 8;
    private static final long MINUTE_NANOS = 60_000_000_000L;

    private final Reporter reporter;
    private final String origin;
    private final LongSupplier nanos;
    private double tokens = BURST;
    private long refilledAt;
    private long lastSummary;
    private long dropped;
    private final Map<String, Long> droppedFrom = new LinkedHashMap<>();
    private long droppedOther;

    /** @param origin the packet-log origin of summaries, e.g. the driver's UID */
    public RejectSampler(Reporter reporter, String origin) {
        this(reporter, origin, System::nanoTime);
    }

    RejectSampler(Reporter reporter, String origin, LongSupplier nanos) {
        this.reporter = reporter;
        this.origin = origin;
        this.nanos = nanos;
        this.refilledAt = nanos.getAsLong();
        this.lastSummary = refilledAt;
    }

    /**
     * One rejected frame: written to the packet log while the budget lasts, otherwise counted for the summary.
     *
     * @param source where it came from, as the packet log's origin (e.g. {@code 127.0.0.2:5000})
     * @param note   why it was rejected
     */
    public void rejected(String source, byte[] raw, String note) {
        boolean keep;
        synchronized (this) {
            long now = nanos.getAsLong();
            tokens = Math.min(BURST, tokens + (now - refilledAt) * (double) PER_MINUTE / MINUTE_NANOS);
            refilledAt = now;
            keep = tokens >= 1;
            if (keep) {
                tokens -= 1;
            } else {
                dropped++;
                String host = source.replaceFirst(":\\d+$", "");
                if (droppedFrom.containsKey(host) || droppedFrom.size() < NAMED_SOURCES) {
                    droppedFrom.merge(host, 1L, Long::sum);
                } else {
                    droppedOther++;
                }
            }
        }
        if (keep) {
            reporter.packet(Direction.RECEIVED, source, raw, note);
        }
        flush(false);
    }

    /** Writes the summary of frames not kept if a minute has passed since the last one; call it on a tick. */
    public void flush() {
        flush(false);
    }

    /** Writes the summary of frames not kept now, if there are any (e.g. before the link closes). */
    public void flushNow() {
        flush(true);
    }

    private void flush(boolean now) {
        String note;
        synchronized (this) {
            long t = nanos.getAsLong();
            if (dropped == 0 || (!now && t - lastSummary < MINUTE_NANOS)) {
                return;
            }
            StringBuilder s = new StringBuilder().append(dropped)
                    .append(" rejected frames not kept in the packet log (flood; every one is counted in the ")
                    .append("driver's rejected.* parameters): ");
            droppedFrom.forEach((host, n) -> s.append(n).append(" from ").append(host).append(", "));
            if (droppedOther > 0) {
                s.append(droppedOther).append(" from other sources, ");
            }
            note = s.substring(0, s.length() - 2);
            dropped = 0;
            droppedOther = 0;
            droppedFrom.clear();
            lastSummary = t;
        }
        reporter.packet(Direction.RECEIVED, origin, new byte[0], note);
    }

    /** @return frames counted but not yet summarised */
    public synchronized long pending() {
        return dropped;
    }
}

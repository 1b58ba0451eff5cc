package org.tinysep.device.support.lifecycle;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import org.tinysep.api.device.Parameter;

/**
 * One setting of an actuator in the thesis actuator model: the device sends a command once, and only the node's
 * own status report says what the setting is. Holds the value the node last reported, the requested value that
 * no report has confirmed yet, and tells the device when the reported value changed.
 * <p>
 * A request stays pending until a report equals it (confirmed) or until a report that disagrees with it arrives
 * {@code patience} or more after the request, in platform time (given up: the node contradicted it). A disagreeing
 * report that arrives sooner is no contradiction: the node may have sent it before the command reached it (it
 * reports on its own schedule, and its reports may wait in the bus radio's queue). The protocols carry no echo of
 * a command, so time is the only evidence; a patience of two report intervals leaves the node one whole interval
 * to answer. The give-up line names the report that contradicted the request (value and time). A newer request
 * replaces an older one. Every step is written to the event log through {@code events}.
 * <p>
 * Thread-safe: requests come from any thread, reports from the bus radio's receive thread. No callback runs while
 * the lock is held.
 *
 * @param <T> the value type, with a meaningful {@code equals} (e.g. {@code Percent}, {@code Boolean})
 */
public final class ConfirmedSetting<T> {

    /** Key of {@link #pendingParameter()}. */
    public static final String PENDING = "pending";

    private final Function<? super T, String> describe;
    private final Duration patience;
    private final Supplier<Instant> clock;
    private final Consumer<String> events;
    private T reported;
    private T pending;
    private Instant requestedAt;

    /**
     * @param describe names a value for the event log, e.g. {@code v -> "potency " + v}
     * @param patience how long after a request a disagreeing report still may predate the command (positive); a
     *                 disagreeing report at or after it gives the request up. Two of the node's report intervals
     * @param clock    the platform time of a request (a device passes {@code this::now})
     * @param events   receives the event-log lines (a device passes {@code this::event})
     */
    public ConfirmedSetting(Function<? super T, String> describe, Duration patience, Supplier<Instant> clock,
            Consumer<String> events) {
        if (patience.isNegative() || patience.isZero()) {
            throw new IllegalArgumentException("patience must be positive, was " + patience);
        }
        this.describe = Objects.requireNonNull(describe, "describe");
        this.patience = patience;
        this.clock = Objects.requireNonNull(clock, "clock");
        this.events = Objects.requireNonNull(events, "events");
    }

    /**
     * Remembers {@code value} as pending since now, then runs {@code send}, then writes "… requested" to the event
     * log. A send that throws is written to the event log after it, not propagated, and the request is forgotten.
     *
     * @return whether the command was handed over
     */
    public boolean request(T value, Runnable send) {
        Objects.requireNonNull(value, "value");
        Instant now = Objects.requireNonNull(clock.get(), "clock");
        synchronized (this) {
            pending = value;
            requestedAt = now;
        }
        RuntimeException failed = null;
        try {
            send.run();
        } catch (RuntimeException e) {
            failed = e;
            synchronized (this) {
                if (pending == value) {
                    pending = null;
                }
            }
        }
        // said after the send, in the same order: writing an entry wakes the event log's threads, which on a
        // 2-core gateway took the CPU from the command on its way (issue 29)
        events.accept(describe.apply(value) + " requested");
        if (failed != null) {
            events.accept(describe.apply(value) + " not sent: " + failed.getMessage());
            return false;
        }
        return true;
    }

    /**
     * Takes the value the node reports.
     *
     * @param at the platform time of the report (as the bus radio stamped it)
     * @return the value if it differs from the previous report (or is the first), empty otherwise
     */
    public Optional<T> report(T value, Instant at) {
        Objects.requireNonNull(value, "value");
        Objects.requireNonNull(at, "at");
        List<String> lines = new ArrayList<>(2);
        boolean changed;
        synchronized (this) {
            changed = !value.equals(reported);
            reported = value;
            boolean confirmed = value.equals(pending);
            if (changed || confirmed) {
                lines.add(describe.apply(value) + (confirmed ? " (confirmed)" : ""));
            }
            if (confirmed) {
                pending = null;
            } else if (pending != null && !at.isBefore(requestedAt.plus(patience))) {
                lines.add(describe.apply(pending) + " not confirmed: the node reported " + describe.apply(value)
                        + " at " + at + ", " + Duration.between(requestedAt, at).toSeconds()
                        + " s after the request (" + requestedAt + "); request given up");
                pending = null;
            }
        }
        lines.forEach(events);
        return changed ? Optional.of(value) : Optional.empty();
    }

    /** @return the value the node last reported; empty before its first report */
    public synchronized Optional<T> value() {
        return Optional.ofNullable(reported);
    }

    /** @return the requested value no report has confirmed yet, if any */
    public synchronized Optional<T> pending() {
        return Optional.ofNullable(pending);
    }

    /** @return the read-only parameter {@value #PENDING}: the pending request, empty when there is none */
    public Parameter pendingParameter() {
        return Parameter.readOnly(PENDING, pending().orElse(null),
                "requested, not yet confirmed by the node's status report");
    }
}

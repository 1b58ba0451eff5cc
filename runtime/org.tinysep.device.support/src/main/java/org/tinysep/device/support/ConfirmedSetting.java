package org.tinysep.device.support;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Function;
import org.tinysep.api.device.Parameter;

/**
 * One setting of an actuator in the thesis actuator model: the device sends a command once, and only the node's
 * own status report says what the setting is. Holds the value the node last reported, the requested value that
 * no report has confirmed yet, and tells the device when the reported value changed.
 * <p>
 * A request stays pending until a report equals it (confirmed) or until {@code patience} reports in a row
 * disagree with it (given up: the node did not take the command; the first disagreeing report may have been on
 * its way before the command arrived). A newer request replaces an older one. Every step is written to the
 * event log through {@code events}.
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
    private final int patience;
    private final Consumer<String> events;
    private T reported;
    private T pending;
    private int disagreements;

    /**
     * @param describe names a value for the event log, e.g. {@code v -> "potency " + v}
     * @param patience how many reports in a row may disagree with a request before it is given up, at least 1
     * @param events   receives the event-log lines (a device passes {@code this::event})
     */
    public ConfirmedSetting(Function<? super T, String> describe, int patience, Consumer<String> events) {
        if (patience < 1) {
            throw new IllegalArgumentException("patience must be at least 1, was " + patience);
        }
        this.describe = Objects.requireNonNull(describe, "describe");
        this.patience = patience;
        this.events = Objects.requireNonNull(events, "events");
    }

    /**
     * Remembers {@code value} as pending, then runs {@code send}. A send that throws is written to the event log,
     * not propagated, and the request is forgotten.
     *
     * @return whether the command was handed over
     */
    public boolean request(T value, Runnable send) {
        Objects.requireNonNull(value, "value");
        synchronized (this) {
            pending = value;
            disagreements = 0;
        }
        events.accept(describe.apply(value) + " requested");
        try {
            send.run();
            return true;
        } catch (RuntimeException e) {
            synchronized (this) {
                if (pending == value) {
                    pending = null;
                }
            }
            events.accept(describe.apply(value) + " not sent: " + e.getMessage());
            return false;
        }
    }

    /**
     * Takes the value the node reports.
     *
     * @return the value if it differs from the previous report (or is the first), empty otherwise
     */
    public Optional<T> report(T value) {
        Objects.requireNonNull(value, "value");
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
            } else if (pending != null && ++disagreements >= patience) {
                lines.add(describe.apply(pending) + " not confirmed: the node still reports " + describe.apply(value)
                        + " after " + disagreements + " status report(s); request given up");
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

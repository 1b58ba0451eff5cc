package org.tinysep.amica.busradio.base;

import java.time.Instant;
import java.util.ArrayDeque;
import java.util.List;
import java.util.function.LongSupplier;

/**
 * What a bus device keeps for a listener that replaces one that just left — typically the abstraction device of a
 * driver being updated: from the moment a listener disconnects, valid payloads are held (at most {@link #CAPACITY},
 * for at most {@link #WINDOW_NANOS}); the next listener to connect gets them replayed, in order and with their
 * original receive instants, before any live payload. Listeners that stayed connected are not affected.
 *
 * <p>With several listeners of one node gone at once, each replacement gets everything since the first left: none
 * is lost, one may see a payload twice. Not thread-safe: the bus device holds its lock around every call.
 */
final class Handover {

    /** A payload held for a replacement listener. */
    record Held(byte[] payload, Instant at) {
    }

    /** How long after the last listener left payloads are still held (10 s). */
    static final long WINDOW_NANOS = 10_000_000_000L;
    /** Most payloads held per bus device; later ones are counted as lost. */
    static final int CAPACITY = 10_000;

    private final LongSupplier nanos;
    private final ArrayDeque<Held> held = new ArrayDeque<>();
    private int outstanding;
    private long lastLeft;
    private long lost;

    Handover(LongSupplier nanos) {
        this.nanos = nanos;
    }

    /** A listener disconnected: hold what comes until its replacement connects. */
    void listenerLeft() {
        outstanding++;
        lastLeft = nanos.getAsLong();
    }

    /**
     * A payload arrived (it goes live to the listeners still connected).
     *
     * @return whether it is held for a replacement
     */
    boolean record(byte[] payload, Instant at) {
        if (!holding()) {
            return false;
        }
        hold(new Held(payload.clone(), at));
        return true;
    }

    /** Holds a payload after those held so far (one that missed a listener as it left). */
    void hold(Held h) {
        if (held.size() < CAPACITY) {
            held.add(h);
        } else {
            lost++;
        }
    }

    /**
     * A listener disconnected with payloads still queued for it ({@link org.tinysep.device.support.delivery.GuardedLane}): they were never
     * given to it and are older than anything held from now on, so they come first.
     */
    void listenerLeft(List<Held> undelivered) {
        listenerLeft();
        for (int i = undelivered.size() - 1; i >= 0; i--) {
            if (held.size() < CAPACITY) {
                held.addFirst(undelivered.get(i));
            } else {
                lost++;
            }
        }
    }

    /** A listener connected: @return the payloads it should get first (empty when nobody left recently) */
    List<Held> claim() {
        if (!holding()) {
            return List.of();
        }
        List<Held> replay = List.copyOf(held);
        if (--outstanding == 0) {
            held.clear();
        }
        return replay;
    }

    /** @return whether a listener left within the window and its replacement has not connected yet */
    boolean awaitingReplacement() {
        return holding();
    }

    /** @return payloads that found the buffer full since creation */
    long lost() {
        return lost;
    }

    private boolean holding() {
        if (outstanding > 0 && nanos.getAsLong() - lastLeft > WINDOW_NANOS) {
            outstanding = 0; // nobody came back in time: the driver was removed, not updated
            held.clear();
        }
        return outstanding > 0;
    }
}

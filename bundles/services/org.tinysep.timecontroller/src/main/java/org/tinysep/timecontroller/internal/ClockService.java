package org.tinysep.timecontroller.internal;

import java.time.Instant;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.TimeControllerListener;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.device.support.lifecycle.Listeners;

/**
 * The {@link TimeControllerProvider} service of the Time Controller device: the clock plus its listeners.
 * Listener calls ({@code timeAdvanced}, {@code modeChanged}) are never concurrent and always in clock order:
 * real-time ticks, synchroniser ticks and mode switches all fire under one lock, and a real-time tick that
 * arrives after a switch to EXTERNAL fires nothing.
 */
final class ClockService implements TimeControllerProvider, SyncProtocol.Target {

    private final String deviceUid;
    private final SyncClock clock;
    private final Listeners<TimeControllerListener> listeners;
    private final Object fireLock = new Object();
    private final LongSupplier nanos;
    /** {@link #nanos} when the synchroniser last moved the clock, or the clock last switched to EXTERNAL. */
    private volatile long lastSync;

    ClockService(String deviceUid, SyncClock clock) {
        this(deviceUid, clock, System::nanoTime);
    }

    /** @param nanos a monotonic clock in nanoseconds (a test's hand-moved one) for {@link #silentFor} */
    ClockService(String deviceUid, SyncClock clock, LongSupplier nanos) {
        this.deviceUid = deviceUid;
        this.clock = clock;
        this.listeners = new Listeners<>(deviceUid);
        this.nanos = nanos;
        this.lastSync = nanos.getAsLong();
    }

    /**
     * @return true when the clock is EXTERNAL and neither a TICK nor the switch to EXTERNAL happened for at least
     *         {@code seconds} (&gt; 0): the synchroniser has finished or gone
     */
    boolean silentFor(long seconds) {
        return seconds > 0 && clock.mode() == ClockMode.EXTERNAL
                && nanos.getAsLong() - lastSync >= seconds * 1_000_000_000L;
    }

    /** One tick of real time: fires {@code timeAdvanced(now)} while in REAL mode, nothing otherwise. */
    void realTick() {
        synchronized (fireLock) {
            if (clock.mode() == ClockMode.REAL) {
                Instant now = clock.now();
                listeners.fire(l -> l.timeAdvanced(this, now));
            }
        }
    }

    @Override
    public SyncClock.TickResult tick(long seq, Instant at) {
        synchronized (fireLock) {
            SyncClock.TickResult r = clock.tick(seq, at);
            if (r.outcome() == SyncClock.Outcome.ADVANCED || r.outcome() == SyncClock.Outcome.REPEATED) {
                lastSync = nanos.getAsLong();
            }
            if (r.outcome() == SyncClock.Outcome.ADVANCED) {
                listeners.fire(l -> l.timeAdvanced(this, r.now()));
            }
            return r;
        }
    }

    /**
     * Switches the clock and tells the listeners ({@code modeChanged}); {@code before} runs first, under the same
     * lock, e.g. to write the event log.
     *
     * @return the time right after the switch, empty when the clock already was in that mode
     */
    Optional<Instant> switchTo(ClockMode mode, Consumer<Instant> before) {
        synchronized (fireLock) {
            Optional<Instant> at = clock.switchTo(mode);
            if (mode == ClockMode.EXTERNAL) {
                lastSync = nanos.getAsLong();
            }
            at.ifPresent(t -> {
                before.accept(t);
                listeners.fire(l -> l.modeChanged(this, mode, t));
            });
            return at;
        }
    }

    int listenerCount() {
        return listeners.size();
    }

    void closeAll() {
        listeners.closeAll();
    }

    @Override
    public Instant now() {
        return clock.now();
    }

    @Override
    public ClockMode mode() {
        return clock.mode();
    }

    @Override
    public String deviceUid() {
        return deviceUid;
    }

    @Override
    public Connection connect(TimeControllerListener listener) {
        return listeners.add(listener);
    }
}

package org.tinysep.timecontroller.internal;

import java.time.Instant;
import java.util.Optional;
import java.util.function.Consumer;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.TimeControllerListener;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.device.support.Listeners;

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

    ClockService(String deviceUid, SyncClock clock) {
        this.deviceUid = deviceUid;
        this.clock = clock;
        this.listeners = new Listeners<>(deviceUid);
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

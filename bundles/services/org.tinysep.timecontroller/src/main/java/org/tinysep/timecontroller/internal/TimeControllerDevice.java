package org.tinysep.timecontroller.internal;

import java.time.Instant;
import java.util.List;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Uids;
import org.tinysep.device.support.lifecycle.WholeFlatDevice;

/**
 * The one Time Controller device (thesis 4.4.3.4), created as soon as the driver starts: it needs no other device.
 * Provides {@link TimeControllerProvider}; in REAL mode its own scheduler ticks every real second (on the
 * second boundary); in EXTERNAL mode only the synchroniser's TICKs move the clock.
 */
final class TimeControllerDevice extends WholeFlatDevice {

    private final ClockService clock;
    private final Consumer<ClockMode> modeRequests;
    private final ScheduledExecutorService realTicks;
    private volatile String link = "";
    private volatile long syncTimeout;

    /** @param modeRequests handles a user's request to switch (parameter {@code mode}): switches and persists */
    TimeControllerDevice(DriverContext context, SyncClock clock, Consumer<ClockMode> modeRequests) {
        super(context, Uids.of(context.driverName(), "clock"), context.driverName(), "Platform clock");
        this.clock = new ClockService(uid(), clock);
        this.modeRequests = modeRequests;
        this.realTicks = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "time-controller-real"));
        publish(this.clock, TimeControllerProvider.class);
    }

    @Override
    protected void onRegistered() {
        long toNextSecond = 1000 - System.currentTimeMillis() % 1000;
        realTicks.scheduleAtFixedRate(this::second, toNextSecond, 1000, TimeUnit.MILLISECONDS);
        status(DeviceStatus.State.ONLINE, clock.mode() + " time");
    }

    ClockService clock() {
        return clock;
    }

    /** @param seconds how long EXTERNAL may go without a TICK before the clock returns to REAL; 0: forever */
    void syncTimeout(long seconds) {
        syncTimeout = seconds;
    }

    /** Every real second: the real-time tick, and the end of EXTERNAL time when the synchroniser has gone silent. */
    private void second() {
        clock.realTick();
        long timeout = syncTimeout;
        if (clock.silentFor(timeout)) {
            switchTo(ClockMode.REAL, "no TICK from the time synchroniser for " + timeout + " s (syncTimeout): it "
                    + "has finished or gone, so the platform follows the system clock again");
        }
    }

    /** Switches the clock; a switch is logged and announced to the listeners. */
    boolean switchTo(ClockMode mode, String why) {
        return clock.switchTo(mode, at -> {
            event("clock switched to " + mode + " (" + why + "), now " + at
                    + (mode == ClockMode.EXTERNAL ? "; held until the synchroniser's first TICK" + (syncTimeout > 0
                            ? ", back to REAL after " + syncTimeout + " s without one" : "") : ""));
            status(DeviceStatus.State.ONLINE, mode + " time");
        }).isPresent();
    }

    /** @param state the synchroniser link's state, shown as a parameter */
    void link(String state) {
        link = state;
    }

    /** {@code mode} is kept in ConfigAdmin (etc/*.cfg), the source of truth; not in the system backup. */
    @Override
    protected boolean backedUp(String key) {
        return !"mode".equals(key);
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(
                Parameter.writable("mode", clock.mode(), "REAL or EXTERNAL (lock-step with the time synchroniser)"),
                Parameter.readOnly("now", clock.now(), "the platform time"),
                Parameter.readOnly("syncLink", link, "the synchroniser's UDP link (docs/time-sync.md)"),
                Parameter.readOnly("listeners", clock.listenerCount(), "connected TimeControllerListeners"));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"mode".equals(key)) {
            throw unknownParameter(key);
        }
        modeRequests.accept(Modes.parse(value));
    }

    @Override
    protected void onDispose() {
        realTicks.shutdownNow();
        clock.closeAll();
    }

    @Override
    public String toString() {
        return super.toString() + " " + clock.mode() + " " + clock.now();
    }
}

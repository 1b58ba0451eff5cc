package org.tinysep.flatoccupancy.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.Optional;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.device.support.lifecycle.AbstractDriver;
import org.tinysep.device.support.lifecycle.ProviderTracker;
import org.tinysep.device.support.rooms.UnmonitoredRooms;
import org.tinysep.device.support.time.PlatformTicker;

/**
 * Flat Occupancy driver: creates its single device when the first Movement or Door interface appears (thesis Fig
 * 3.3) and connects it to every later one. The device watches the person: left without any it stays (a
 * deliberate deviation from thesis 3.3, docs/architecture.md) and says which rooms it can no longer see.
 */
@Component(service = {}, immediate = true, configurationPid = FlatOccupancyDriver.PID)
@Designate(ocd = FlatOccupancyConfig.class)
public final class FlatOccupancyDriver extends AbstractDriver {

    static final String PID = "org.tinysep.flatoccupancy";
    static final String NAME = "FlatOccupancy";

    private Duration leaveTimeout;
    private Duration exitGrace;
    private ProviderTracker<MovementProvider> movements;
    private ProviderTracker<DoorProvider> doors;
    private ProviderTracker<WindowProvider> windows;
    private final Map<String, WindowProvider> windowsSeen = new ConcurrentHashMap<>();
    private ProviderTracker<PresenceProvider> presences;
    private PlatformTicker ticker;
    private UnmonitoredRooms unmonitored;

    public FlatOccupancyDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, FlatOccupancyConfig config) {
        leaveTimeout = Duration.ofSeconds(Math.max(10, config.leaveTimeoutSeconds()));
        exitGrace = Duration.ofSeconds(Math.min(Math.max(0, config.exitGraceSeconds()), leaveTimeout.toSeconds() - 1));
        start(bundleContext);
        ticker = PlatformTicker.whenDue(bundleContext, "flat-occupancy", this::tick); // before the device
        unmonitored = new UnmonitoredRooms(bundleContext);
        movements = new ProviderTracker<>(bundleContext, MovementProvider.class, null, ProviderTracker.Callback.of(
                (movement, uid) -> device().watch(movement), (movement, uid) -> providerGone(uid))).open();
        doors = new ProviderTracker<>(bundleContext, DoorProvider.class, null, ProviderTracker.Callback.of(
                (door, uid) -> device().watch(door), (door, uid) -> providerGone(uid))).open();
        presences = new ProviderTracker<>(bundleContext, PresenceProvider.class, null, ProviderTracker.Callback.of(
                (p, uid) -> device().watch(p), (p, uid) -> gone(uid))).open();
        // windows only join an existing device (the thesis creates it for movement and doors, Fig 3.3)
        windows = new ProviderTracker<>(bundleContext, WindowProvider.class, null, ProviderTracker.Callback.of(
                (w, uid) -> {
                    windowsSeen.put(uid, w);
                    existing().ifPresent(d -> d.watch(w));
                }, (w, uid) -> {
                    windowsSeen.remove(uid);
                    gone(uid);
                })).open();
    }

    @Deactivate
    void deactivate() {
        ticker.close();
        windows.close();
        presences.close();
        movements.close();
        doors.close();
        stop();
        unmonitored.close();
    }

    /** A tick when a leave check ends; @return when the next one ends, null without one (or without a device) */
    private Instant tick(Instant now) {
        List<FlatOccupancyDevice> all = devices(FlatOccupancyDevice.class);
        return all.isEmpty() ? null : all.get(0).tick(now);
    }

    private void gone(String uid) {
        existing().ifPresent(d -> d.forget(uid));
        providerGone(uid);
    }

    private Optional<FlatOccupancyDevice> existing() {
        List<FlatOccupancyDevice> all = devices(FlatOccupancyDevice.class);
        return all.isEmpty() ? Optional.empty() : Optional.of(all.get(0));
    }

    /** @return the single device, created on first need; windows present then join it */
    private synchronized FlatOccupancyDevice device() {
        List<FlatOccupancyDevice> all = devices(FlatOccupancyDevice.class);
        if (!all.isEmpty()) {
            return all.get(0);
        }
        FlatOccupancyDevice d = addDevice(new FlatOccupancyDevice(context(), leaveTimeout, exitGrace));
        d.unmonitored(this::unmonitoredRooms);
        d.whenDue(ticker::wake);
        windowsSeen.values().forEach(d::watch);
        return d;
    }

    /** @return e.g. "Bathroom (no sensor heard since 2026-11-25T09:12:00Z)", or "" (all heard, or no Sensor Health) */
    private String unmonitoredRooms() {
        return unmonitored.now().stream().map(u -> u.roomName() + " (no sensor heard since " + u.since() + ")")
                .collect(java.util.stream.Collectors.joining(", "));
    }
}

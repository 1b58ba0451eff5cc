package org.tinysep.flatoccupancy.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.device.support.AbstractDriver;
import org.tinysep.device.support.PlatformTicker;
import org.tinysep.device.support.ProviderTracker;

/**
 * Flat Occupancy driver: creates its single device when the first Movement or Door interface appears (thesis Fig
 * 3.3) and connects it to every later one; a device left without any is removed, and created anew when one
 * appears again.
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
    private PlatformTicker ticker;

    public FlatOccupancyDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, FlatOccupancyConfig config) {
        leaveTimeout = Duration.ofSeconds(Math.max(10, config.leaveTimeoutSeconds()));
        exitGrace = Duration.ofSeconds(Math.min(Math.max(0, config.exitGraceSeconds()), leaveTimeout.toSeconds() - 1));
        start(bundleContext);
        movements = new ProviderTracker<>(bundleContext, MovementProvider.class, null, ProviderTracker.Callback.of(
                (movement, uid) -> device().watch(movement), (movement, uid) -> providerGone(uid))).open();
        doors = new ProviderTracker<>(bundleContext, DoorProvider.class, null, ProviderTracker.Callback.of(
                (door, uid) -> device().watch(door), (door, uid) -> providerGone(uid))).open();
        ticker = new PlatformTicker(bundleContext, "flat-occupancy", this::tick);
    }

    @Deactivate
    void deactivate() {
        ticker.close();
        movements.close();
        doors.close();
        stop();
    }

    private void tick(Instant now) {
        List<FlatOccupancyDevice> all = devices(FlatOccupancyDevice.class);
        if (!all.isEmpty()) {
            all.get(0).tick(now);
        }
    }

    /** @return the single device, created on first need */
    private synchronized FlatOccupancyDevice device() {
        List<FlatOccupancyDevice> all = devices(FlatOccupancyDevice.class);
        return all.isEmpty() ? addDevice(new FlatOccupancyDevice(context(), leaveTimeout, exitGrace)) : all.get(0);
    }
}

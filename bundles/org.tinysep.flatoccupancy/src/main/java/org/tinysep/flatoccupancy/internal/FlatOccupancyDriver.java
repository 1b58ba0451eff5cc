package org.tinysep.flatoccupancy.internal;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.device.support.AbstractDriver;
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
    private static final Logger LOG = LoggerFactory.getLogger(FlatOccupancyDriver.class);

    private Duration leaveTimeout;
    private Duration exitGrace;
    private ProviderTracker<MovementProvider> movements;
    private ProviderTracker<DoorProvider> doors;
    private ScheduledExecutorService ticker;

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
        ticker = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "flat-occupancy-tick"));
        ticker.scheduleAtFixedRate(this::tick, 1, 1, TimeUnit.SECONDS);
    }

    @Deactivate
    void deactivate() {
        ticker.shutdownNow();
        movements.close();
        doors.close();
        stop();
    }

    private void tick() {
        try {
            List<FlatOccupancyDevice> all = devices(FlatOccupancyDevice.class);
            if (!all.isEmpty()) {
                all.get(0).tick(context().now());
            }
        } catch (RuntimeException e) {
            LOG.warn("Flat occupancy tick failed; the next one follows in a second: {}", e.toString());
        }
    }

    /** @return the single device, created on first need */
    private synchronized FlatOccupancyDevice device() {
        List<FlatOccupancyDevice> all = devices(FlatOccupancyDevice.class);
        return all.isEmpty() ? addDevice(new FlatOccupancyDevice(context(), leaveTimeout, exitGrace)) : all.get(0);
    }
}

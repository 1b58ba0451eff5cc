package org.tinysep.followmelight.internal;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.BiConsumer;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.metatype.annotations.Designate;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.device.support.AbstractDriver;
import org.tinysep.device.support.PlatformTicker;
import org.tinysep.device.support.ProviderTracker;
import org.tinysep.device.support.TrackedPlacements;

/**
 * Follow Me Light driver: creates its single device when the first light (simple or dimmable) appears and
 * connects it to every later one; movement, pet movement, Flat Occupancy and House Information are connected
 * whenever present. A device left without lights is removed and created anew with the next light.
 */
@Component(service = {}, immediate = true, configurationPid = FollowMeDriver.PID)
@Designate(ocd = FollowMeConfig.class)
public final class FollowMeDriver extends AbstractDriver {

    static final String PID = "org.tinysep.followmelight";
    static final String NAME = "FollowMeLight";

    private final Map<String, Object> optional = new ConcurrentHashMap<>();
    private final List<ProviderTracker<?>> trackers = new ArrayList<>();
    private Duration grace;
    private Percent brightness;
    private TrackedPlacements directory;
    private PlatformTicker ticker;

    public FollowMeDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, FollowMeConfig config) {
        grace = Duration.ofSeconds(Math.min(3600, Math.max(5, config.graceSeconds())));
        brightness = Percent.of(Math.min(100, Math.max(1, config.brightness())));
        start(bundleContext);
        directory = new TrackedPlacements(bundleContext);
        track(bundleContext, FlatOccupancyProvider.class);
        track(bundleContext, HouseInformationProvider.class);
        track(bundleContext, MovementProvider.class);
        track(bundleContext, PetMovementProvider.class);
        light(bundleContext, SimpleLightProvider.class, (d, p) -> d.control(p));
        light(bundleContext, DimmableLightProvider.class, (d, p) -> d.control(p));
        ticker = new PlatformTicker(bundleContext, "follow-me-light", now -> current().forEach(d -> d.tick(now)));
    }

    @Deactivate
    void deactivate() {
        ticker.close();
        for (int i = trackers.size() - 1; i >= 0; i--) {
            trackers.get(i).close();
        }
        trackers.clear();
        stop();
        directory.close();
    }

    private <P> void light(BundleContext bc, Class<P> type, BiConsumer<FollowMeDevice, P> control) {
        trackers.add(new ProviderTracker<>(bc, type, null, ProviderTracker.Callback.of(
                (p, uid) -> control.accept(device(), p), (p, uid) -> {
                    current().forEach(d -> d.forget(uid));
                    providerGone(uid);
                })).open());
    }

    private <P> void track(BundleContext bc, Class<P> type) {
        trackers.add(new ProviderTracker<>(bc, type, null, ProviderTracker.Callback.of((p, uid) -> {
            optional.put(type.getName() + '/' + uid, p);
            current().forEach(d -> attach(d, p));
        }, (p, uid) -> {
            optional.remove(type.getName() + '/' + uid);
            current().forEach(d -> d.forget(uid));
            providerGone(uid);
        })).open());
    }

    private static void attach(FollowMeDevice d, Object p) {
        if (p instanceof FlatOccupancyProvider f) {
            d.use(f);
        } else if (p instanceof HouseInformationProvider h) {
            d.use(h);
        } else if (p instanceof MovementProvider m) {
            d.use(m);
        } else if (p instanceof PetMovementProvider m) {
            d.use(m);
        }
    }

    private List<FollowMeDevice> current() {
        return devices(FollowMeDevice.class);
    }

    /** @return the single device, created (and connected to the optional providers) on first need */
    private synchronized FollowMeDevice device() {
        List<FollowMeDevice> all = current();
        if (!all.isEmpty()) {
            return all.get(0);
        }
        FollowMeDevice d = addDevice(new FollowMeDevice(context(), directory, grace, brightness));
        optional.values().forEach(p -> attach(d, p));
        return d;
    }
}

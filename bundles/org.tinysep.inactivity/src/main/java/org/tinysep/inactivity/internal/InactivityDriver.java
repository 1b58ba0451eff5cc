package org.tinysep.inactivity.internal;

import java.time.ZoneId;
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
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.device.support.AbstractDriver;
import org.tinysep.device.support.PlatformTicker;
import org.tinysep.device.support.ProviderTracker;
import org.tinysep.device.support.TrackedPlacements;

/**
 * Inactivity Recognition driver: creates its single device when the first activity source (Movement, Door or
 * Window) appears and connects it to every later one; Flat Occupancy, Mail Manager and House Information are
 * connected whenever present. A device left without sources is removed and created anew with the next one.
 */
@Component(service = {}, immediate = true, configurationPid = InactivityDriver.PID)
@Designate(ocd = InactivityConfig.class)
public final class InactivityDriver extends AbstractDriver {

    static final String PID = "org.tinysep.inactivity";
    static final String NAME = "InactivityRecognition";
    private static final Logger LOG = LoggerFactory.getLogger(InactivityDriver.class);

    private final Map<String, Object> optional = new ConcurrentHashMap<>();
    private final List<ProviderTracker<?>> trackers = new ArrayList<>();
    private LimitTable limits;
    private AlertMail words;
    private TrackedPlacements directory;
    private PlatformTicker ticker;

    public InactivityDriver() {
        super(NAME);
    }

    @Activate
    void activate(BundleContext bundleContext, InactivityConfig config) {
        limits = LimitTable.parse(config.defaultLimitMinutes(), config.typeLimits(), config.roomLimits());
        words = new AlertMail(zone(config.timeZone()));
        start(bundleContext);
        directory = new TrackedPlacements(bundleContext);
        track(bundleContext, FlatOccupancyProvider.class);
        track(bundleContext, MailManagerProvider.class);
        track(bundleContext, HouseInformationProvider.class);
        source(bundleContext, MovementProvider.class, (d, p) -> d.watch(p));
        source(bundleContext, DoorProvider.class, (d, p) -> d.watch(p));
        source(bundleContext, WindowProvider.class, (d, p) -> d.watch(p));
        ticker = new PlatformTicker(bundleContext, "inactivity", now -> current().forEach(d -> d.tick(now)));
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

    private <P> void source(BundleContext bc, Class<P> type, BiConsumer<InactivityDevice, P> watch) {
        trackers.add(new ProviderTracker<>(bc, type, null, ProviderTracker.Callback.of(
                (p, uid) -> watch.accept(device(), p), (p, uid) -> providerGone(uid))).open());
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

    private static void attach(InactivityDevice d, Object p) {
        if (p instanceof FlatOccupancyProvider f) {
            d.use(f);
        } else if (p instanceof MailManagerProvider m) {
            d.use(m);
        } else if (p instanceof HouseInformationProvider h) {
            d.use(h);
        }
    }

    private List<InactivityDevice> current() {
        return devices(InactivityDevice.class);
    }

    /** @return the single device, created (and connected to the optional providers) on first need */
    private synchronized InactivityDevice device() {
        List<InactivityDevice> all = current();
        if (!all.isEmpty()) {
            return all.get(0);
        }
        InactivityDevice d = addDevice(new InactivityDevice(context(), directory, limits, words));
        optional.values().forEach(p -> attach(d, p));
        return d;
    }

    private ZoneId zone(String id) {
        if (id == null || id.isBlank()) {
            return ZoneId.systemDefault();
        }
        try {
            return ZoneId.of(id.strip());
        } catch (RuntimeException e) {
            LOG.warn("timeZone '{}' is not a time zone ({}); using {}", id, e.getMessage(), ZoneId.systemDefault());
            return ZoneId.systemDefault();
        }
    }
}

package org.tinysep.falldetection.internal;

import java.util.List;
import java.util.function.BiFunction;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.Connection;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.device.support.lifecycle.ServiceUse;
import org.tinysep.device.support.rooms.TrackedPlacements;

/**
 * Feeds {@link LastSeen} from the platform: every movement, door and presence sensor and House Information, tracked
 * as they come and go (all optional: without them the alert says that no room was seen yet).
 */
final class LastSeenWatch implements AutoCloseable {

    private final LastSeen seen;
    private final TrackedPlacements placements;
    private final List<ServiceTracker<?, Connection>> trackers;

    LastSeenWatch(BundleContext context) {
        placements = new TrackedPlacements(context);
        seen = new LastSeen(placements);
        trackers = List.of(
                track(context, MovementProvider.class, (p, s) -> p.connect(s)),
                track(context, DoorProvider.class, (p, s) -> p.connect(s)),
                track(context, PresenceProvider.class, (p, s) -> p.connect(s)),
                track(context, HouseInformationProvider.class, (p, s) -> {
                    s.rooms(p.rooms());
                    return p.connect((src, rooms, at) -> s.rooms(rooms));
                }));
        trackers.forEach(ServiceTracker::open);
    }

    LastSeen lastSeen() {
        return seen;
    }

    private <S> ServiceTracker<S, Connection> track(BundleContext context, Class<S> type,
            BiFunction<S, LastSeen, Connection> connect) {
        return new ServiceTracker<>(context, type, null) {
            @Override
            public Connection addingService(ServiceReference<S> ref) {
                // no use left in the registry per sensor: Felix's per-bundle use array made n sensors cost n²
                S service = ServiceUse.take(context, ref);
                if (service == null) {
                    return null;
                }
                try {
                    return connect.apply(service, seen);
                } catch (RuntimeException e) { // a provider going away while connecting
                    ServiceUse.release(context, ref);
                    return null;
                }
            }

            @Override
            public void removedService(ServiceReference<S> ref, Connection c) {
                c.close();
                ServiceUse.release(context, ref);
            }
        };
    }

    @Override
    public void close() {
        trackers.forEach(ServiceTracker::close);
        placements.close();
    }
}

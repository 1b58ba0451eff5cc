package org.tinysep.device.support.rooms;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.HouseInformationListener;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;

/**
 * The rooms devices can be placed in: the current House Information provider when one is installed. Devices watch
 * it to forget a room that was removed. Without House Information, placing a device fails with a clear message.
 */
public final class RoomDirectory implements AutoCloseable {

    /** The message when no House Information provider is present. */
    public static final String NO_HOUSE = "no House Information installed; install org.tinysep.houseinformation"
            + " to place devices in rooms";

    private final Supplier<HouseInformationProvider> house;
    private final CopyOnWriteArrayList<Consumer<List<Room>>> watchers = new CopyOnWriteArrayList<>();
    private final HouseInformationListener relay = this::relay;
    private volatile Runnable onClose = () -> { };

    private RoomDirectory(Supplier<HouseInformationProvider> house) {
        this.house = house;
    }

    /** A directory without House Information (unit tests, tools). */
    public static RoomDirectory none() {
        return new RoomDirectory(() -> null);
    }

    /** A directory over one given provider, connected at once (unit tests). */
    public static RoomDirectory of(HouseInformationProvider provider) {
        RoomDirectory d = new RoomDirectory(() -> provider);
        Connection c = provider.connect(d.relay);
        d.onClose = c::close;
        return d;
    }

    /**
     * A directory over the House Information provider {@code house} supplies, whose changes reach it through
     * {@link #listenTo}: for a caller that follows the provider services itself (a driver context follows its
     * platform services with one service listener).
     *
     * @since 1.1
     */
    public static RoomDirectory over(Supplier<HouseInformationProvider> house) {
        return new RoomDirectory(house);
    }

    /**
     * Relays the changes of a House Information provider that came to this directory's watchers.
     *
     * @return closes the relay (when the provider goes)
     * @since 1.1
     */
    public Connection listenTo(HouseInformationProvider provider) {
        return provider.connect(relay);
    }

    /** A directory following the HouseInformationProvider services as they come and go. */
    public static RoomDirectory tracking(BundleContext context) {
        AtomicReference<ServiceTracker<HouseInformationProvider, HouseInformationProvider>> holder =
                new AtomicReference<>();
        RoomDirectory d = new RoomDirectory(() -> holder.get().getService());
        ServiceTracker<HouseInformationProvider, HouseInformationProvider> tracker = new ServiceTracker<>(context,
                HouseInformationProvider.class, null) {
            private final Map<ServiceReference<?>, Connection> connections = new ConcurrentHashMap<>();

            @Override
            public HouseInformationProvider addingService(ServiceReference<HouseInformationProvider> ref) {
                HouseInformationProvider p = super.addingService(ref);
                if (p != null) {
                    connections.put(ref, p.connect(d.relay));
                }
                return p;
            }

            @Override
            public void removedService(ServiceReference<HouseInformationProvider> ref, HouseInformationProvider p) {
                Connection c = connections.remove(ref);
                if (c != null) {
                    c.close();
                }
                try {
                    super.removedService(ref, p);
                } catch (IllegalStateException ignored) {
                    // our bundle is stopping
                }
            }
        };
        holder.set(tracker);
        tracker.open();
        d.onClose = tracker::close;
        return d;
    }

    /** @return the House Information provider, when one is installed */
    public Optional<HouseInformationProvider> house() {
        return Optional.ofNullable(house.get());
    }

    /**
     * @return the room {@code query} names (UID, unique UID prefix, or exact name)
     * @throws IllegalArgumentException when there is no House Information or no single matching room
     */
    public Room resolve(String query) {
        HouseInformationProvider h = house.get();
        if (h == null) {
            throw new IllegalArgumentException(NO_HOUSE);
        }
        return Rooms.resolve(h.rooms(), query);
    }

    /** @return the room with that UID, if House Information is present and knows it */
    public Optional<Room> room(String uid) {
        HouseInformationProvider h = house.get();
        return h == null ? Optional.empty() : h.room(uid);
    }

    /**
     * Calls {@code onChange} with the whole plan after every change of the house.
     *
     * @return closes the watch
     */
    public Connection watch(Consumer<List<Room>> onChange) {
        watchers.add(onChange);
        return new Connection() {
            @Override
            public void close() {
                watchers.remove(onChange);
            }

            @Override
            public boolean isOpen() {
                return watchers.contains(onChange);
            }
        };
    }

    private void relay(HouseInformationProvider source, List<Room> rooms, Instant at) {
        for (Consumer<List<Room>> w : watchers) {
            w.accept(rooms);
        }
    }

    @Override
    public void close() {
        watchers.clear();
        onClose.run();
    }
}

package org.tinysep.device.support.lifecycle;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.Connection;

/**
 * The platform services a driver context follows (event and packet log, clock, house, backup store), through one
 * service listener: each of them as its own {@link ServiceTracker} made 5 listeners per driver, and Felix matches
 * every service event (each device registered or removed) against every listener of the framework: 26 drivers made
 * ~130 of the ~250 listeners each device's registration visited (issue 29, item 4). Like a tracker, the service of
 * each type is the best ranked one present.
 */
final class PlatformServices implements AutoCloseable {

    private final List<Class<?>> types;
    private final ServiceTracker<Object, Object> tracker;
    private final Map<ServiceReference<Object>, Object> present = new ConcurrentHashMap<>();
    /** What {@code follow} opened for each service, closed when it goes. */
    private final Map<ServiceReference<Object>, Connection> followed = new ConcurrentHashMap<>();
    /** The best service of each type, replaced as a whole on every change (read on every event entry). */
    private volatile Map<Class<?>, Object> best = Map.of();

    /**
     * @param follow told each service as it comes; the connection it returns (or null) is closed when it goes
     */
    PlatformServices(BundleContext context, List<Class<?>> types, Function<Object, Connection> follow) {
        this.types = List.copyOf(types);
        StringBuilder f = new StringBuilder("(|");
        types.forEach(t -> f.append('(').append(Constants.OBJECTCLASS).append('=').append(t.getName()).append(')'));
        try {
            tracker = new ServiceTracker<>(context, FrameworkUtil.createFilter(f.append(')').toString()), null) {
                @Override
                public Object addingService(ServiceReference<Object> ref) {
                    Object s = super.addingService(ref);
                    if (s != null) {
                        present.put(ref, s);
                        choose();
                        Connection c = follow.apply(s);
                        if (c != null) {
                            followed.put(ref, c);
                        }
                    }
                    return s;
                }

                @Override
                public void modifiedService(ServiceReference<Object> ref, Object s) {
                    choose(); // its ranking may have changed
                }

                @Override
                public void removedService(ServiceReference<Object> ref, Object s) {
                    Connection c = followed.remove(ref);
                    if (c != null) {
                        c.close();
                    }
                    present.remove(ref);
                    choose();
                    try {
                        super.removedService(ref, s);
                    } catch (IllegalStateException stopping) {
                        // our bundle is stopping: the framework releases its uses
                    }
                }
            };
        } catch (InvalidSyntaxException e) {
            throw new IllegalArgumentException("bad platform service types " + types, e);
        }
        tracker.open();
    }

    /** @return the best ranked service of that type present now, or null */
    <T> T get(Class<T> type) {
        return type.cast(best.get(type));
    }

    /** Recomputes the best ranked service of each type. */
    private synchronized void choose() {
        Map<Class<?>, Object> next = new HashMap<>();
        Map<Class<?>, ServiceReference<Object>> refs = new HashMap<>();
        present.forEach((ref, service) -> {
            for (Class<?> t : types) {
                ServiceReference<Object> now = refs.get(t);
                if (t.isInstance(service) && (now == null || ref.compareTo(now) > 0)) {
                    refs.put(t, ref);
                    next.put(t, service);
                }
            }
        });
        best = Map.copyOf(next);
    }

    @Override
    public void close() {
        tracker.close();
        best = Map.of();
    }
}

package org.tinysep.itests;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BiFunction;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.device.Connection;

/**
 * A test's connections to every provider of some types, made as each provider appears and closed as it goes, like
 * any consumer of the platform.
 */
public final class Connections implements AutoCloseable {

    private final List<ServiceTracker<?, ?>> trackers = new ArrayList<>();
    private final BundleContext context;

    public Connections(BundleContext context) {
        this.context = context;
    }

    /** Connects to every present and future provider of {@code type} through {@code connector}. */
    public <P> Connections to(Class<P> type, BiFunction<ServiceReference<P>, P, Connection> connector) {
        ServiceTracker<P, Connection> tracker = new ServiceTracker<>(context, type, null) {
            @Override
            public Connection addingService(ServiceReference<P> ref) {
                return connector.apply(ref, context.getService(ref));
            }

            @Override
            public void removedService(ServiceReference<P> ref, Connection c) {
                c.close();
                context.ungetService(ref);
            }
        };
        tracker.open();
        trackers.add(tracker);
        return this;
    }

    @Override
    public void close() {
        trackers.forEach(ServiceTracker::close);
    }
}

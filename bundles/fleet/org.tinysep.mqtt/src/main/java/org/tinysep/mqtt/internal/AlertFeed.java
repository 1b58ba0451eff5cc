package org.tinysep.mqtt.internal;

import java.util.concurrent.Executor;
import java.util.function.Consumer;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.device.Connection;

/**
 * Follows the alert service: hears every alert change (handed to the bridge's thread at once, so the alert service
 * never waits) and tells the bridge when a service appears (to publish what changed meanwhile).
 */
final class AlertFeed implements AutoCloseable {

    private final ServiceTracker<AlertService, AlertService> tracker;
    private volatile AlertService current;
    private volatile Connection connection;

    AlertFeed(BundleContext context, Executor executor, Consumer<Alert> changed, Consumer<AlertService> added) {
        tracker = new ServiceTracker<>(context, AlertService.class, null) {
            @Override
            public AlertService addingService(ServiceReference<AlertService> ref) {
                AlertService s = super.addingService(ref);
                if (s != null && current == null) {
                    current = s;
                    connection = s.connect(a -> executor.execute(() -> changed.accept(a)));
                    executor.execute(() -> added.accept(s));
                }
                return s;
            }

            @Override
            public void removedService(ServiceReference<AlertService> ref, AlertService s) {
                if (s == current) {
                    Connection c = connection;
                    if (c != null) {
                        c.close();
                    }
                    current = null;
                }
                super.removedService(ref, s);
            }
        };
        tracker.open();
    }

    AlertService service() {
        return current;
    }

    @Override
    public void close() {
        tracker.close();
    }
}

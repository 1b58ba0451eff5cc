package org.tinysep.runtime.internal.directory;

import java.util.function.Supplier;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceReference;
import org.tinysep.device.support.lifecycle.Safely;

/** Small helpers shared by the service-tracker customizers. */
final class Tracking {

    private Tracking() {
    }

    static long serviceId(ServiceReference<?> ref) {
        Object id = ref.getProperty(Constants.SERVICE_ID);
        return id instanceof Long l ? l : -1L;
    }

    /** @return the service property as text, else what {@code fallback} says (an exception there gives "") */
    static String string(ServiceReference<?> ref, String key, Supplier<String> fallback) {
        Object value = ref.getProperty(key);
        return value != null ? value.toString() : Safely.get(fallback, "");
    }

    static void unget(BundleContext context, ServiceReference<?> ref) {
        try {
            context.ungetService(ref);
        } catch (IllegalStateException ignored) {
            // our bundle context is already invalid: nothing to release
        }
    }
}

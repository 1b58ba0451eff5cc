package org.tinysep.device.support.lifecycle;

import java.util.function.BiConsumer;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.Filter;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.DeviceProperties;

/**
 * Tracks the providers of one interface, optionally narrowed by an LDAP filter on their properties (the thesis's
 * "new interface found / removed" notifications). Callbacks run on the thread that registered or unregistered
 * the service; a callback that throws is logged, never propagated into the service registry.
 *
 * @param <P> the provider interface
 */
public final class ProviderTracker<P> implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(ProviderTracker.class);

    /** What to do when a matching provider appears or goes. */
    public interface Callback<P> {
        void added(P provider, String providerDeviceUid);

        void removed(P provider, String providerDeviceUid);

        /** @return a callback made of two lambdas */
        static <P> Callback<P> of(BiConsumer<P, String> added, BiConsumer<P, String> removed) {
            return new Callback<>() {
                @Override
                public void added(P provider, String providerDeviceUid) {
                    added.accept(provider, providerDeviceUid);
                }

                @Override
                public void removed(P provider, String providerDeviceUid) {
                    removed.accept(provider, providerDeviceUid);
                }
            };
        }
    }

    private final ServiceTracker<P, P> tracker;

    /**
     * @param extraFilter an LDAP filter on service properties, or null for every provider of {@code type}
     */
    public ProviderTracker(BundleContext context, Class<P> type, String extraFilter, Callback<P> callback) {
        String f = "(" + Constants.OBJECTCLASS + "=" + type.getName() + ")";
        if (extraFilter != null && !extraFilter.isBlank()) {
            f = "(&" + f + extraFilter + ")";
        }
        Filter filter;
        try {
            filter = FrameworkUtil.createFilter(f);
        } catch (InvalidSyntaxException e) {
            throw new IllegalArgumentException("bad provider filter " + f + ": " + e.getMessage(), e);
        }
        this.tracker = new ServiceTracker<>(context, filter, null) {
            @Override
            public P addingService(ServiceReference<P> ref) {
                P p = ServiceUse.take(context, ref); // no use left in the registry per provider
                if (p == null) {
                    return null;
                }
                try {
                    callback.added(p, uidOf(ref));
                } catch (RuntimeException e) {
                    LOG.warn("Handling new {} from device {} failed: {}", type.getSimpleName(), uidOf(ref), e.toString());
                    LOG.debug("detail", e);
                }
                return p;
            }

            @Override
            public void removedService(ServiceReference<P> ref, P p) {
                try {
                    callback.removed(p, uidOf(ref));
                } catch (RuntimeException e) {
                    LOG.warn("Handling removal of {} from device {} failed: {}", type.getSimpleName(), uidOf(ref),
                            e.toString());
                    LOG.debug("detail", e);
                } finally {
                    ServiceUse.release(context, ref);
                }
            }
        };
    }

    private static String uidOf(ServiceReference<?> ref) {
        Object uid = ref.getProperty(DeviceProperties.DEVICE_UID);
        return uid == null ? "service-" + ref.getProperty(Constants.SERVICE_ID) : uid.toString();
    }

    /** Starts tracking; providers already registered are reported at once. */
    public ProviderTracker<P> open() {
        tracker.open();
        return this;
    }

    /** Stops tracking; every tracked provider is reported as removed. */
    @Override
    public void close() {
        tracker.close();
    }
}

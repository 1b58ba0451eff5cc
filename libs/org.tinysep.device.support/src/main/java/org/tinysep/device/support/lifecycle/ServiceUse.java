package org.tinysep.device.support.lifecycle;

import java.util.function.Function;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceObjects;
import org.osgi.framework.ServiceReference;

/**
 * Service objects of devices taken without leaving a use behind in the framework's registry.
 * <p>
 * Felix keeps the services each bundle uses in one array per bundle: every new use searches and copies it, every
 * unregistration scans every bundle's array, and a use given back with {@code BundleContext.ungetService} stays in
 * it (count 0) until the service goes. So a consumer that took one service object per device made creating and
 * stopping n devices cost n² (JFR, RESULTS.md closing notes). A use taken and given back through
 * {@link ServiceObjects} is removed from the array at once, so these arrays stay as short as the services in use
 * at this moment.
 * <p>
 * {@link #take} is for trackers that keep the object: a service of singleton scope (a device's services, registered
 * as plain objects) is the same object for every bundle and has nothing to release, so it is given back at once and
 * the object kept; any other (a service factory, e.g. a Declarative Services component that a last release may
 * deactivate) is held until {@link #release}.
 */
public final class ServiceUse {

    private ServiceUse() {
    }

    /**
     * Calls {@code use} with the service and gives it back at once.
     *
     * @return what {@code use} returned, or {@code gone} when the service is no longer registered (or this bundle
     *         is stopping)
     */
    public static <S, R> R with(BundleContext context, ServiceReference<S> ref, Function<? super S, R> use, R gone) {
        ServiceObjects<S> objects;
        S service;
        try {
            objects = context.getServiceObjects(ref);
            service = objects == null ? null : objects.getService();
        } catch (IllegalStateException stopping) {
            return gone;
        }
        if (service == null) {
            return gone;
        }
        try {
            return use.apply(service);
        } finally {
            giveBack(objects, service);
        }
    }

    /**
     * @return the service object to keep (null when the service is gone); a singleton's use is already given back,
     *         any other's is held until {@link #release}
     */
    public static <S> S take(BundleContext context, ServiceReference<S> ref) {
        if (!singleton(ref)) {
            return context.getService(ref);
        }
        ServiceObjects<S> objects = context.getServiceObjects(ref);
        S service = objects == null ? null : objects.getService();
        if (service != null) {
            giveBack(objects, service);
        }
        return service;
    }

    /** Gives back what {@link #take} held: nothing for a singleton. Safe while this bundle is stopping. */
    public static void release(BundleContext context, ServiceReference<?> ref) {
        if (singleton(ref)) {
            return;
        }
        try {
            context.ungetService(ref);
        } catch (IllegalStateException stopping) {
            // this bundle is stopping: the framework releases its uses
        }
    }

    /** @return whether the service is one object for all bundles (registered as a plain object, not a factory) */
    static boolean singleton(ServiceReference<?> ref) {
        return Constants.SCOPE_SINGLETON.equals(ref.getProperty(Constants.SERVICE_SCOPE));
    }

    private static <S> void giveBack(ServiceObjects<S> objects, S service) {
        try {
            objects.ungetService(service);
        } catch (IllegalStateException | IllegalArgumentException gone) {
            // unregistered meanwhile, or this bundle is stopping: nothing is held any more
        }
    }
}

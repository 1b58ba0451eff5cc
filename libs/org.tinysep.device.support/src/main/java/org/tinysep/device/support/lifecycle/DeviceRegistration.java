package org.tinysep.device.support.lifecycle;

import java.util.List;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Provider;
import org.tinysep.api.log.EventKind;

/**
 * A device's identity and its place in the service registry, both ways: the services it provides (the
 * {@link Device} service and its providers, with the identity properties) and the connections it holds as a
 * consumer, each announced in the event log.
 */
final class DeviceRegistration {

    private final DriverContext context;
    private final String uid;
    private final DeviceServices services = new DeviceServices();
    private final Consumptions consumptions = new Consumptions();
    /** The provider objects connected to, by their device UID (to name a lost source in words). */
    private final java.util.Map<String, Object> providers = new java.util.concurrent.ConcurrentHashMap<>();

    DeviceRegistration(DriverContext context, String uid, String type) {
        this.context = context;
        this.uid = uid;
        services.property(DeviceProperties.DEVICE_UID, uid);
        services.property(DeviceProperties.DEVICE_TYPE, type);
        services.property(DeviceProperties.DRIVER_UID, context.driverUid());
        services.property(DeviceProperties.DRIVER_NAME, context.driverName());
    }

    void publish(Object provider, Class<?>... interfaces) {
        services.publish(provider, interfaces);
    }

    /** Sets (or with null removes) a service property on all of the device's services. */
    void property(String key, Object value) {
        services.property(key, value);
    }

    Object property(String key) {
        return services.property(key);
    }

    void register(Device device) {
        services.register(context.bundleContext(), device);
    }

    <L> void connect(Provider<L> provider, Class<?> providerInterface, L listener, boolean vital) {
        consumptions.add(providerInterface.getSimpleName(), provider.deviceUid(), vital, provider.connect(listener));
        providers.put(provider.deviceUid(), provider);
        context.consumers().connected(provider.deviceUid(), uid);
        context.reporter().event(EventKind.CONNECTED, uid, "connected to " + providerInterface.getSimpleName()
                + " of " + provider.deviceUid() + (vital ? " (vital)" : " (optional)"));
    }

    /** Drops every connection to the given provider device. @return whether a vital connection is still held */
    boolean providerGone(String providerUid) {
        providers.remove(providerUid);
        context.consumers().disconnected(providerUid, uid);
        for (ConnectionInfo c : consumptions.to(providerUid)) {
            if (consumptions.remove(c.interfaceName(), providerUid)) {
                context.reporter().event(EventKind.DISCONNECTED, uid, "disconnected from " + c.interfaceName()
                        + " of " + providerUid + " (provider removed)");
            }
        }
        return consumptions.hasVital();
    }

    /** @return the provider object of that device UID while connected to it, or null */
    Object provider(String providerUid) {
        return providers.get(providerUid);
    }

    List<ConnectionInfo> connections() {
        return consumptions.infos();
    }

    /** @return the connections held to one provider device */
    List<ConnectionInfo> connectionsTo(String providerUid) {
        return consumptions.to(providerUid);
    }

    /** Closes every connection, then unregisters the services. */
    void unregister() {
        // inputs before services: once its inputs are closed, what arrives for this device waits for a replacement
        // (a bus device's Handover); had the services gone first, a payload arriving in between would reach this
        // device with no consumer left to tell (lost during a driver update)
        for (ConnectionInfo c : consumptions.infos()) {
            context.reporter().event(EventKind.DISCONNECTED, uid, "disconnected from " + c.interfaceName() + " of "
                    + c.providerDeviceUid());
            context.consumers().disconnected(c.providerDeviceUid(), uid);
        }
        consumptions.closeAll();
        providers.clear();
        services.unregister();
    }
}

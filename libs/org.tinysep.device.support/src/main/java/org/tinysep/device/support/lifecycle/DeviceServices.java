package org.tinysep.device.support.lifecycle;

import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;
import org.tinysep.api.device.Device;

/**
 * The OSGi services of one device: its {@link Device} service and its provider interfaces, all carrying the same
 * properties. The Device service is registered first and unregistered first. Consumers react to the providers
 * synchronously (creating or removing their own devices), so this order makes the device manager's event log
 * read cause before effect: "bus device created", then "AmicaMovement created", then "FlatOccupancy created".
 */
final class DeviceServices {

    private record Published(Object service, String[] interfaces) {
    }

    private final List<Published> published = new ArrayList<>();
    private final Hashtable<String, Object> properties = new Hashtable<>();
    private final List<ServiceRegistration<?>> registrations = new ArrayList<>();
    /** Counts property changes, so a registration that raced with one is brought up to date. */
    private long version;

    void publish(Object service, Class<?>... interfaces) {
        String[] names = new String[interfaces.length];
        for (int i = 0; i < interfaces.length; i++) {
            names[i] = interfaces[i].getName();
        }
        published.add(new Published(service, names));
    }

    synchronized void property(String key, Object value) {
        version++;
        if (value == null) {
            properties.remove(key);
        } else {
            properties.put(key, value);
        }
        for (ServiceRegistration<?> r : registrations) {
            try {
                r.setProperties(properties);
            } catch (IllegalStateException ignored) {
                // already unregistered
            }
        }
    }

    synchronized Object property(String key) {
        return properties.get(key);
    }

    void register(BundleContext context, Device device) {
        long v = version();
        add(context.registerService(Device.class, device, snapshot()), v);
        for (Published p : published) {
            v = version();
            add(context.registerService(p.interfaces, p.service, snapshot()), v);
        }
    }

    private synchronized long version() {
        return version;
    }

    private synchronized Hashtable<String, Object> snapshot() {
        return new Hashtable<>(properties);
    }

    /** Keeps a new registration; a property changed while it was being registered is applied to it now. */
    private synchronized void add(ServiceRegistration<?> r, long registeredAt) {
        registrations.add(r);
        if (registeredAt != version) {
            try {
                r.setProperties(properties);
            } catch (IllegalStateException ignored) {
                // already unregistered
            }
        }
    }

    void unregister() {
        List<ServiceRegistration<?>> regs;
        synchronized (this) {
            regs = new ArrayList<>(registrations);
            registrations.clear();
        }
        for (ServiceRegistration<?> r : regs) { // the Device service first, as registered
            try {
                r.unregister();
            } catch (IllegalStateException ignored) {
                // already gone, e.g. the bundle is stopping
            }
        }
    }
}

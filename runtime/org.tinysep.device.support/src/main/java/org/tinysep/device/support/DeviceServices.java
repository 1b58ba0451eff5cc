package org.tinysep.device.support;

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

    void publish(Object service, Class<?>... interfaces) {
        String[] names = new String[interfaces.length];
        for (int i = 0; i < interfaces.length; i++) {
            names[i] = interfaces[i].getName();
        }
        published.add(new Published(service, names));
    }

    synchronized void property(String key, Object value) {
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
        Hashtable<String, Object> props;
        synchronized (this) {
            props = new Hashtable<>(properties);
        }
        add(context.registerService(Device.class, device, props));
        for (Published p : published) {
            add(context.registerService(p.interfaces, p.service, props));
        }
    }

    private synchronized void add(ServiceRegistration<?> r) {
        registrations.add(r);
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

package org.tinysep.device.support.lifecycle;

import java.util.ArrayList;
import java.util.Hashtable;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.backup.ComponentKind;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;

/**
 * Common part of every driver: identity, its Driver service, its device list, and the thesis 3.3 removal rules.
 * Subclasses are immediate Declarative Services components with {@code service = {}} that call
 * {@link #start(BundleContext)} on activation and {@link #stop()} on deactivation; stopping removes every device
 * one by one before the driver itself goes.
 */
public abstract class AbstractDriver implements Driver {

    private final String name;
    private final String uid;
    private final Map<String, AbstractDevice> devices = new LinkedHashMap<>();
    private volatile DriverContext context;
    private volatile ServiceRegistration<Driver> registration;
    /** Devices examined because a provider went, counted for the scale test (RegistryUsesTest). */
    long examined;

    protected AbstractDriver(String name) {
        this.name = name;
        this.uid = Uids.driver(name);
    }

    /** Prepares the driver's context and registers its {@link Driver} service. */
    protected final void start(BundleContext bundleContext) {
        start(bundleContext, Map.of());
    }

    /**
     * Prepares the driver's context and registers its {@link Driver} service with the standard properties plus
     * {@code extraProperties} (e.g. a bound port).
     */
    protected final void start(BundleContext bundleContext, Map<String, Object> extraProperties) {
        context = new DriverContext(bundleContext, uid, name);
        Hashtable<String, Object> props = new Hashtable<>(extraProperties);
        props.put(DeviceProperties.DRIVER_UID, uid);
        props.put(DeviceProperties.DRIVER_NAME, name);
        registration = bundleContext.registerService(Driver.class, this, props);
        context.backups().save(new ComponentBackup(uid, ComponentKind.DRIVER, uid, name, name, name, Map.of(), "",
                List.of(), null, Map.of(), context.now())); // the driver's own file (docs/backup.md)
    }

    /**
     * Replaces the extra properties of the registered {@link Driver} service (the standard ones stay), e.g. a state
     * others filter on or show; does nothing before {@link #start} or after {@link #stop()}.
     */
    protected final void driverProperties(Map<String, Object> extraProperties) {
        ServiceRegistration<Driver> r = registration;
        if (r == null) {
            return;
        }
        Hashtable<String, Object> props = new Hashtable<>(extraProperties);
        props.put(DeviceProperties.DRIVER_UID, uid);
        props.put(DeviceProperties.DRIVER_NAME, name);
        try {
            r.setProperties(props);
        } catch (IllegalStateException ignored) {
            // unregistered meanwhile: the driver is stopping
        }
    }

    /**
     * Removes every device, one by one in creation order (each removal announced by the service registry), then
     * unregisters the Driver service and releases the context.
     */
    protected final void stop() {
        for (AbstractDevice d : snapshot()) {
            remove(d.uid()); // their backups stay: they come back on the next start
        }
        ServiceRegistration<Driver> r = registration;
        registration = null;
        if (r != null) {
            try {
                r.unregister();
            } catch (IllegalStateException ignored) {
                // the bundle is already stopping
            }
        }
        DriverContext c = context;
        if (c != null) {
            c.close();
        }
    }

    /**
     * The usual deactivation of a driver with parts of its own (a socket, a serial radio, a ticker): closes the
     * given parts in order (null ones, never opened, are skipped), then {@link #stop()}. Written once for the bus
     * radios; a part that throws on close stops the deactivation there.
     *
     * @param parts what the driver opened, e.g. its ticker first, then its transport
     */
    protected final void stop(AutoCloseable... parts) {
        Closeables.closeInOrder(name, parts);
        stop();
    }

    protected final DriverContext context() {
        DriverContext c = context;
        if (c == null) {
            throw new IllegalStateException(name + " is not started");
        }
        return c;
    }

    /**
     * Registers a newly constructed device and adds it to this driver's list. When the backup store holds a backup
     * of the device (same UID), its saved settings are applied first, so it registers as it was (thesis 3.7).
     */
    protected final <D extends AbstractDevice> D addDevice(D device) {
        synchronized (devices) {
            if (devices.containsKey(device.uid())) {
                throw new IllegalStateException(name + " already has device " + device.uid());
            }
            devices.put(device.uid(), device);
        }
        context().backups().find(device.uid()).ifPresent(device::restore);
        device.register();
        return device;
    }

    /**
     * @return the backups of this driver's devices from before the restart: a bus radio re-creates its known
     *         nodes from them before it opens its hardware (docs/backup.md)
     */
    protected final List<ComponentBackup> savedDevices() {
        return context().backups().devicesOf(uid);
    }

    /**
     * Tells every device that a provider device went away; a device left without a vital connection is removed
     * (thesis 3.3), unless it watches the person ({@link AbstractDevice#watchesThePerson()}: it stays and
     * says which room it can no longer see). While the driver's own bundle is stopping, its closing trackers report every provider as
     * removed: that is the driver going, not the providers, so nothing is done here and {@link #stop()} removes
     * the devices one by one instead (no false "lost its vital connections" entries).
     */
    protected final void providerGone(String providerUid) {
        DriverContext own = context;
        if (own != null && own.stopping()) {
            return;
        }
        // only the devices connected to it (an index), not every device's connections: n providers going from n
        // devices would cost n²
        for (String deviceUid : context().consumers().consumersOf(providerUid)) {
            AbstractDevice d;
            synchronized (devices) {
                d = devices.get(deviceUid);
            }
            examined++;
            if (d != null && !d.loseProvider(providerUid)) {
                context().event(EventKind.DEVICE_EVENT, d.uid() + " lost its vital connections and is removed");
                remove(d.uid()); // its backup stays: the settings come back with the provider
            }
        }
    }

    /**
     * Removes a device at the user's request (the device manager's {@code remove}): its backup is deleted too, so
     * it is not re-created on the next start.
     */
    @Override
    public final boolean removeDevice(String deviceUid) {
        boolean removed = remove(deviceUid);
        if (removed) {
            context().backups().delete(deviceUid);
        }
        return removed;
    }

    /** Removes a device, keeping its backup. */
    protected final boolean remove(String deviceUid) {
        AbstractDevice d;
        synchronized (devices) {
            d = devices.remove(deviceUid);
        }
        if (d == null) {
            return false;
        }
        d.dispose();
        onDeviceRemoved(d);
        return true;
    }

    /** Called after a device was removed, whatever the reason; e.g. to forget the node it stood for. */
    protected void onDeviceRemoved(AbstractDevice device) {
    }

    /** @return this driver's devices of the given class */
    protected final <D extends AbstractDevice> List<D> devices(Class<D> type) {
        return snapshot().stream().filter(type::isInstance).map(type::cast).toList();
    }

    private List<AbstractDevice> snapshot() {
        synchronized (devices) {
            return new ArrayList<>(devices.values());
        }
    }

    @Override
    public final String uid() {
        return uid;
    }

    @Override
    public final String name() {
        return name;
    }

    @Override
    public final List<Device> devices() {
        return List.copyOf(snapshot());
    }

    @Override
    public List<Parameter> parameters() {
        return List.of();
    }

    @Override
    public String toString() {
        return name + " " + uid;
    }
}

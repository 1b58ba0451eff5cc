package org.tinysep.runtime.internal.shell;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.Parameter;
import org.tinysep.device.support.lifecycle.Safely;
import org.tinysep.runtime.internal.directory.DeviceRecord;
import org.tinysep.runtime.internal.directory.DeviceView;
import org.tinysep.runtime.internal.directory.DriverRecord;
import org.tinysep.runtime.internal.directory.DriverView;
import org.tinysep.runtime.internal.directory.Inventory;
import org.tinysep.runtime.internal.directory.Lookup;
import org.tinysep.runtime.internal.directory.UidResolver;
import org.tinysep.runtime.internal.directory.Views;

/**
 * What the shell (and later the web UI) can do with drivers and devices (thesis 3.8, IGuiDeviceManager). Devices
 * are named by UID or a unique UID prefix of at least 4 characters; drivers by UID or name. Errors are thrown as
 * {@link IllegalArgumentException} (bad input) or {@link IllegalStateException} (the operation failed), each
 * with a one-line message for the user.
 */
public final class Operations {

    /** Stops a bundle persistently (its autostart setting becomes stopped) and returns its symbolic name. */
    @FunctionalInterface
    interface BundleControl {
        String stop(long bundleId) throws Exception;
    }

    /** The read-only parameter of an actuator's request the node has not confirmed (ConfirmedSetting.PENDING). */
    static final String PENDING = "pending";

    private final Inventory inventory;
    private final BundleControl bundles;
    private final long ownBundleId;

    Operations(Inventory inventory, BundleControl bundles, long ownBundleId) {
        this.inventory = inventory;
        this.bundles = bundles;
        this.ownBundleId = ownBundleId;
    }

    List<DriverView> drivers() {
        return Views.drivers(inventory);
    }

    List<DeviceView> devices() {
        return Views.devices(inventory);
    }

    /** @return the devices {@code filter} names ({@link DeviceFilter}); all when it is empty */
    List<DeviceView> devices(String filter) {
        return DeviceFilter.apply(devices(), filter);
    }

    /** Removes a device (exact UID or unique prefix) or else a driver (UID, name or unique UID prefix). */
    String remove(String query) {
        String q = query == null ? "" : query.strip();
        if (q.isEmpty()) {
            throw new IllegalArgumentException("give a device uid or a driver uid or name");
        }
        List<String> deviceUids = inventory.devices().stream().map(DeviceRecord::uid).toList();
        if (deviceUids.contains(q)) {
            return removeDevice(q);
        }
        if (!Lookup.driversNamed(inventory, q).isEmpty()) {
            return removeDriver(q);
        }
        List<String> devices = UidResolver.matches(q, deviceUids);
        List<String> drivers = UidResolver.matches(q, inventory.drivers().stream().map(DriverRecord::uid).toList());
        if (devices.size() + drivers.size() == 1) {
            return devices.isEmpty() ? removeDriver(drivers.get(0)) : removeDevice(devices.get(0));
        }
        if (devices.isEmpty() && drivers.isEmpty()) {
            throw new IllegalArgumentException("no device or driver matches '" + q + "' (give a device uid or a "
                    + "unique prefix of at least " + UidResolver.MIN_PREFIX + " characters, or a driver uid or name)");
        }
        List<String> all = new ArrayList<>(devices);
        all.addAll(drivers);
        throw UidResolver.ambiguous(q, all);
    }

    /** Asks the owning driver (the one whose {@code uid()} is the device's driver UID) to remove the device. */
    String removeDevice(String query) {
        DeviceRecord device = Lookup.device(inventory, query);
        DriverRecord owner = inventory.drivers().stream().filter(d -> d.uid().equals(device.driverUid()))
                .findFirst().orElseThrow(() -> new IllegalStateException("device " + device.uid()
                        + " belongs to driver uid '" + device.driverUid() + "', which is not registered"));
        boolean removed;
        try {
            removed = owner.driver().removeDevice(device.uid());
        } catch (RuntimeException e) {
            throw new IllegalStateException("driver " + owner.name() + " failed to remove device " + device.uid()
                    + ": " + Safely.describe(e));
        }
        if (!removed) {
            throw new IllegalStateException("driver " + owner.name() + " says device " + device.uid()
                    + " is not one of its devices; nothing removed");
        }
        return "removed device " + device.uid() + " (" + device.type() + ") of driver " + owner.name();
    }

    /**
     * Stops, persistently, the bundle that registered the driver; the driver's deactivation removes its devices
     * one by one, each removal announced. {@code start <bundleId>} in the Felix shell brings it back.
     */
    String removeDriver(String query) {
        DriverRecord d = Lookup.driver(inventory, query);
        if (d.bundleId() <= 0 || d.bundleId() == ownBundleId) {
            throw new IllegalArgumentException("driver " + d.name() + " is registered by bundle " + d.bundleId()
                    + " (" + d.bundleName() + "), which cannot be stopped from here");
        }
        List<String> others = inventory.drivers().stream()
                .filter(o -> o.bundleId() == d.bundleId() && o.serviceId() != d.serviceId())
                .map(DriverRecord::name).toList();
        String bundleName;
        try {
            bundleName = bundles.stop(d.bundleId());
        } catch (Exception e) {
            throw new IllegalStateException("could not stop bundle " + d.bundleId() + " (" + d.bundleName()
                    + ") of driver " + d.name() + ": " + Safely.describe(e));
        }
        return "stopped bundle " + d.bundleId() + " (" + bundleName + "): driver " + d.name() + " and its devices"
                + (others.isEmpty() ? "" : ", and driver(s) " + String.join(", ", others) + ",")
                + " removed; 'start " + d.bundleId() + "' brings them back";
    }

    String setParameter(String query, String key, String value) {
        DeviceRecord d = Lookup.device(inventory, query);
        if (key == null || key.isBlank()) {
            throw new IllegalArgumentException("give a parameter key");
        }
        List<Parameter> before = Safely.get(() -> d.device().parameters(), List.of());
        try {
            d.device().setParameter(key, value);
        } catch (IllegalArgumentException e) {
            boolean known = before.stream().anyMatch(p -> p.key().equals(key));
            throw new IllegalArgumentException("cannot set " + key + " on " + d.uid() + ": " + reason(e)
                    + (known ? "" : " (parameters: " + keys(before) + ")"));
        } catch (RuntimeException e) {
            throw new IllegalStateException("device " + d.uid() + " failed to set " + key + ": "
                    + Safely.describe(e));
        }
        List<Parameter> after = Safely.get(() -> d.device().parameters(), List.<Parameter>of());
        String now = valueOf(after, key).orElse(value);
        String pending = PENDING.equals(key) ? "" : valueOf(after, PENDING).orElse("");
        String who = d.uid() + ": ";
        String pendingBefore = valueOf(before, PENDING).orElse("");
        if (!pending.isEmpty() && (!pending.equals(pendingBefore) || pending.equals(value))) {
            // an actuator took the request: the node's next status report decides
            return who + key + "=" + pending + " requested, pending until the node confirms it (it reports " + key
                    + "=" + (now.isEmpty() ? "nothing yet" : now) + "; tinysep:events --device " + d.uid()
                    + " shows the answer)";
        }
        return who + key + "=" + now;
    }

    String invoke(String query, String function) {
        DeviceRecord d = Lookup.device(inventory, query);
        if (function == null || function.isBlank()) {
            throw new IllegalArgumentException("give a function name");
        }
        String result;
        try {
            result = d.device().invoke(function);
        } catch (IllegalArgumentException e) {
            List<DeviceFunction> functions = Safely.get(() -> d.device().functions(), List.of());
            throw new IllegalArgumentException("cannot invoke " + function + " on " + d.uid() + ": " + reason(e)
                    + (functions.isEmpty() ? " (it has no functions)"
                            : " (functions: " + String.join(", ",
                                    functions.stream().map(DeviceFunction::name).toList()) + ")"));
        } catch (RuntimeException e) {
            throw new IllegalStateException("device " + d.uid() + " failed to run " + function + ": "
                    + Safely.describe(e));
        }
        return d.uid() + " " + function + ": " + (result == null || result.isBlank() ? "done" : result);
    }

    private static String reason(IllegalArgumentException e) {
        return e.getMessage() == null || e.getMessage().isBlank() ? "rejected" : Safely.oneLine(e.getMessage());
    }

    private static java.util.Optional<String> valueOf(List<Parameter> parameters, String key) {
        return parameters.stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst();
    }

    private static String keys(List<Parameter> parameters) {
        return parameters.isEmpty() ? "none" : String.join(", ", parameters.stream().map(Parameter::key).toList());
    }
}

package org.tinysep.runtime.internal.directory;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.tinysep.device.support.lifecycle.Safely;

/**
 * Builds the shell's views from the inventory, calling the drivers and devices for their live state. A call that
 * throws or returns null does not spoil the listing: it is reported on the view instead.
 */
public final class Views {

    private Views() {
    }

    public static List<DriverView> drivers(Inventory inventory) {
        List<DriverView> out = new ArrayList<>();
        for (DriverRecord d : inventory.drivers()) {
            List<String> errors = new ArrayList<>();
            List<?> devices = live(() -> d.driver().devices(), null, "devices()", errors);
            out.add(new DriverView(d.uid(), d.name(), d.bundleId(),
                    devices == null ? "?" : Integer.toString(devices.size()),
                    live(() -> d.driver().parameters(), List.of(), "parameters()", errors), errors));
        }
        return out;
    }

    public static List<DeviceView> devices(Inventory inventory) {
        Map<String, String> driverNames = new HashMap<>();
        for (DriverRecord d : inventory.drivers()) {
            driverNames.putIfAbsent(d.uid(), d.name());
        }
        List<DeviceView> out = new ArrayList<>();
        for (DeviceRecord r : inventory.devices()) {
            out.add(device(r, driverNames.getOrDefault(r.driverUid(), "?" + r.driverUid()),
                    inventory.interfacesOf(r.uid())));
        }
        return out;
    }

    static DeviceView device(DeviceRecord r, String driverName, List<String> provides) {
        List<String> errors = new ArrayList<>();
        var device = r.device();
        String name = live(device::name, r.name(), "name()", errors);
        String status = live(() -> device.status().toString(), "?", "status()", errors);
        return new DeviceView(r.uid(), r.type(), name, status, driverName, provides,
                live(device::connections, List.of(), "connections()", errors), r.node(),
                live(device::parameters, List.of(), "parameters()", errors),
                live(device::functions, List.of(), "functions()", errors), errors);
    }

    private static <T> T live(Supplier<T> call, T fallback, String what, List<String> errors) {
        try {
            T value = call.get();
            if (value == null) {
                errors.add(what + " returned null");
                return fallback;
            }
            return value;
        } catch (RuntimeException e) {
            errors.add(what + " failed: " + Safely.describe(e));
            return fallback;
        }
    }
}

package org.tinysep.runtime.internal.directory;

import java.util.List;

/** Finds the device or driver a user named. */
public final class Lookup {

    private Lookup() {
    }

    /** @return the device named by its UID or a unique UID prefix */
    public static DeviceRecord device(Inventory inventory, String query) {
        List<DeviceRecord> devices = inventory.devices();
        String uid = UidResolver.resolve(query, devices.stream().map(DeviceRecord::uid).toList(), "device");
        return devices.stream().filter(d -> d.uid().equals(uid)).findFirst().orElseThrow();
    }

    /** @return the drivers whose UID is {@code query}, else those whose name is it (ignoring case) */
    public static List<DriverRecord> driversNamed(Inventory inventory, String query) {
        String q = query == null ? "" : query.strip();
        List<DriverRecord> drivers = inventory.drivers();
        List<DriverRecord> byUid = drivers.stream().filter(d -> d.uid().equals(q)).toList();
        return byUid.isEmpty() ? drivers.stream().filter(d -> d.name().equalsIgnoreCase(q)).toList() : byUid;
    }

    /** @return the driver named by its UID, its name, or a unique UID prefix */
    public static DriverRecord driver(Inventory inventory, String query) {
        List<DriverRecord> named = driversNamed(inventory, query);
        if (named.size() > 1) {
            throw UidResolver.ambiguous(query.strip(), named.stream().map(DriverRecord::uid).toList());
        }
        if (named.size() == 1) {
            return named.get(0);
        }
        List<DriverRecord> drivers = inventory.drivers();
        String uid = UidResolver.resolve(query, drivers.stream().map(DriverRecord::uid).toList(), "driver");
        return drivers.stream().filter(d -> d.uid().equals(uid)).findFirst().orElseThrow();
    }
}

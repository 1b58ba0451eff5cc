package org.tinysep.runtime.internal;

import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The thread-safe store behind {@link Inventory}: drivers, devices and provider services keyed by service id.
 * Lock-free (concurrent maps of immutable records), so service events on any thread never wait here.
 */
final class DeviceDirectory implements Inventory {

    private final Map<Long, DriverRecord> drivers = new ConcurrentHashMap<>();
    private final Map<Long, DeviceRecord> devices = new ConcurrentHashMap<>();
    private final Map<Long, ProviderRecord> providers = new ConcurrentHashMap<>();

    void put(DriverRecord r) {
        drivers.put(r.serviceId(), r);
    }

    void put(DeviceRecord r) {
        devices.put(r.serviceId(), r);
    }

    void put(ProviderRecord r) {
        providers.put(r.serviceId(), r);
    }

    void removeDriver(long serviceId) {
        drivers.remove(serviceId);
    }

    void removeDevice(long serviceId) {
        devices.remove(serviceId);
    }

    void removeProvider(long serviceId) {
        providers.remove(serviceId);
    }

    @Override
    public List<DriverRecord> drivers() {
        return drivers.values().stream()
                .sorted(Comparator.comparing(DriverRecord::name).thenComparing(DriverRecord::uid)
                        .thenComparingLong(DriverRecord::serviceId))
                .toList();
    }

    @Override
    public List<DeviceRecord> devices() {
        return devices.values().stream()
                .sorted(Comparator.comparing(DeviceRecord::uid).thenComparingLong(DeviceRecord::serviceId))
                .toList();
    }

    @Override
    public List<String> interfacesOf(String deviceUid) {
        return providers.values().stream()
                .filter(p -> p.deviceUid().equals(deviceUid))
                .flatMap(p -> p.interfaces().stream())
                .distinct().sorted().toList();
    }
}

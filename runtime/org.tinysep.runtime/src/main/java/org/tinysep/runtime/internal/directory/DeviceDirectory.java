package org.tinysep.runtime.internal.directory;

import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;

/**
 * The thread-safe store behind {@link Inventory}: drivers, devices and provider services keyed by service id.
 * Lock-free (concurrent maps of immutable records), so service events on any thread never wait here. Provider
 * services are also indexed by device UID, so a device's interfaces ({@link #interfacesOf}, asked once per new
 * device) cost the same with 10 or 10,000 devices (a scan of every provider per new device made creation
 * quadratic).
 */
public final class DeviceDirectory implements Inventory {

    private final Map<Long, DriverRecord> drivers = new ConcurrentHashMap<>();
    private final Map<Long, DeviceRecord> devices = new ConcurrentHashMap<>();
    private final Map<Long, ProviderRecord> providers = new ConcurrentHashMap<>();
    /** device UID → its provider services by service id */
    private final Map<String, Map<Long, ProviderRecord>> providersByDevice = new ConcurrentHashMap<>();
    /** provider records read by {@link #interfacesOf} since creation: tests check it does not grow with the count */
    private final LongAdder providersRead = new LongAdder();

    public void put(DriverRecord r) {
        drivers.put(r.serviceId(), r);
    }

    public void put(DeviceRecord r) {
        devices.put(r.serviceId(), r);
    }

    public void put(ProviderRecord r) {
        ProviderRecord old = providers.put(r.serviceId(), r);
        if (old != null && !old.deviceUid().equals(r.deviceUid())) {
            unindex(old);
        }
        providersByDevice.compute(r.deviceUid(), (uid, byId) -> {
            Map<Long, ProviderRecord> m = byId == null ? new ConcurrentHashMap<>() : byId;
            m.put(r.serviceId(), r);
            return m;
        });
    }

    void removeDriver(long serviceId) {
        drivers.remove(serviceId);
    }

    void removeDevice(long serviceId) {
        devices.remove(serviceId);
    }

    void removeProvider(long serviceId) {
        ProviderRecord old = providers.remove(serviceId);
        if (old != null) {
            unindex(old);
        }
    }

    private void unindex(ProviderRecord r) {
        providersByDevice.computeIfPresent(r.deviceUid(), (uid, byId) -> {
            byId.remove(r.serviceId(), r);
            return byId.isEmpty() ? null : byId;
        });
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
        Map<Long, ProviderRecord> own = providersByDevice.get(deviceUid);
        if (own == null) {
            return List.of();
        }
        TreeSet<String> names = new TreeSet<>();
        for (ProviderRecord p : own.values()) {
            providersRead.increment();
            names.addAll(p.interfaces());
        }
        return List.copyOf(names);
    }

    /** @return how many provider records {@link #interfacesOf} has read in all */
    long providersRead() {
        return providersRead.sum();
    }
}

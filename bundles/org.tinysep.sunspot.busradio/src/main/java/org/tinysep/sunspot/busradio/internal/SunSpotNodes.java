package org.tinysep.sunspot.busradio.internal;

import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.UnaryOperator;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.Backups;
import org.tinysep.device.support.DriverContext;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * The node table shared by every link: one bus device per Sun SPOT address, created (and registered through the
 * driver) on the first valid packet from an address, forgotten when the driver removed it. Creation is serialised,
 * so two links hearing a new node at once still create one device. Thread-safe.
 */
final class SunSpotNodes {

    private final Map<SunSpotAddress, SunSpotBusDevice> nodes = new ConcurrentHashMap<>();
    private final Object creating = new Object();
    private final DriverContext context;
    private final String deviceType;
    private final UnaryOperator<SunSpotBusDevice> register;

    /**
     * @param deviceType the type of the bus devices, {@code BusRadioSunSpot}
     * @param register   registers a new bus device with the driver ({@code AbstractDriver.addDevice}); tests
     *                   without a framework pass the identity
     */
    SunSpotNodes(DriverContext context, String deviceType, UnaryOperator<SunSpotBusDevice> register) {
        this.context = context;
        this.deviceType = deviceType;
        this.register = register;
    }

    /** @return the bus device of {@code address}, created and registered now if it is new */
    SunSpotBusDevice findOrCreate(SunSpotAddress address, SunSpotSensorType type, String link) {
        SunSpotBusDevice known = nodes.get(address);
        if (known != null) {
            return known;
        }
        synchronized (creating) {
            known = nodes.get(address);
            if (known != null) {
                return known;
            }
            SunSpotBusDevice device = new SunSpotBusDevice(context, deviceType, address, type, link);
            nodes.put(address, device);
            try {
                return register.apply(device);
            } catch (RuntimeException e) { // e.g. the bundle is stopping: the next packet tries again
                nodes.remove(address, device);
                throw e;
            }
        }
    }

    /** Re-creates the bus devices of the nodes known before the restart; an unusable backup is reported. */
    int restore(List<ComponentBackup> saved) {
        return Backups.recreate(context, saved, b -> SunSpotBusDevice.restored(context, deviceType, b), d -> {
            synchronized (creating) {
                return nodes.putIfAbsent(d.address(), d) == null;
            }
        }, register);
    }

    SunSpotBusDevice find(SunSpotAddress address) {
        return nodes.get(address);
    }

    /** Forgets the node of a removed bus device, so its next packet creates it anew. */
    void forget(AbstractDevice device) {
        if (device instanceof SunSpotBusDevice bus) {
            nodes.remove(bus.address(), bus);
        }
    }

    /** Marks every bus device last heard on {@code link} OFFLINE; each comes back ONLINE with its next packet. */
    void offline(String link, String detail) {
        nodes.values().forEach(d -> d.offline(link, detail));
    }

    /** @return the bus devices, in no particular order */
    List<SunSpotBusDevice> all() {
        return List.copyOf(nodes.values());
    }

    int size() {
        return nodes.size();
    }
}

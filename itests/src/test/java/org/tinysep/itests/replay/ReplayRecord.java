package org.tinysep.itests.replay;

import java.time.Instant;
import java.util.Map;
import java.util.NavigableMap;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentSkipListMap;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.itests.Connections;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;

/**
 * What the platform's devices tell their consumers during a replay: per node address, how many times a sensor
 * turned on (motion detected after none, a door or window opened after being closed, a presence sensor ON after
 * OFF), and Flat Occupancy's changes
 * with their virtual times. It connects to every provider as it appears, like any consumer.
 */
final class ReplayRecord implements AutoCloseable {

    private final Map<String, Integer> onCounts = new ConcurrentHashMap<>();
    private final Map<String, Boolean> lastOn = new ConcurrentHashMap<>();
    private final NavigableMap<Instant, Occupancy> occupancy = new ConcurrentSkipListMap<>();
    private final Connections connections;

    ReplayRecord(BundleContext context) {
        this.connections = new Connections(context);
        connections.to(MovementProvider.class, (ref, p) -> p.connect((src, m) -> sensor(ref, m.detected())));
        connections.to(DoorProvider.class, (ref, p) -> p.connect((src, s, at) -> sensor(ref, s == OpenState.OPEN)));
        connections.to(WindowProvider.class, (ref, p) -> p.connect((src, s, at) -> sensor(ref, s == OpenState.OPEN)));
        connections.to(PresenceProvider.class, (ref, p) -> p.connect((src, on, first, at) -> sensor(ref, on)));
        connections.to(FlatOccupancyProvider.class, (ref, p) -> p.connect((src, o, at) -> occupancy.put(at, o)));
    }

    /** @return node address → times the sensor turned on, sorted */
    NavigableMap<String, Integer> onCounts() {
        return new TreeMap<>(onCounts);
    }

    /** @return virtual time → occupancy entered then */
    NavigableMap<Instant, Occupancy> occupancy() {
        return new TreeMap<>(occupancy);
    }

    private void sensor(ServiceReference<?> ref, boolean on) {
        String address = String.valueOf(ref.getProperty(DeviceProperties.NODE_ADDRESS));
        Boolean before = lastOn.put(address, on);
        if (on && !Boolean.TRUE.equals(before)) {
            onCounts.merge(address, 1, Integer::sum);
        }
    }


    @Override
    public void close() {
        connections.close();
    }
}

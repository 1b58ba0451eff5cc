package org.tinysep.device.support.rooms;

import java.util.List;
import org.osgi.framework.BundleContext;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.health.SensorHealthProvider;
import org.tinysep.api.health.UnmonitoredRoom;

/**
 * The rooms Sensor Health says cannot be heard now, for the services that explain an alert with them (Flat
 * Occupancy, Inactivity Recognition): an optional, dynamic view of whichever {@link SensorHealthProvider} is
 * registered, written once instead of a DS reference in each driver. Open from a driver's activate, close in its
 * deactivate.
 */
public final class UnmonitoredRooms implements AutoCloseable {

    private final ServiceTracker<SensorHealthProvider, SensorHealthProvider> health;

    public UnmonitoredRooms(BundleContext context) {
        health = new ServiceTracker<>(context, SensorHealthProvider.class, null);
        health.open();
    }

    /** @return the unmonitored rooms; empty without Sensor Health, or while it is going away */
    public List<UnmonitoredRoom> now() {
        SensorHealthProvider h = health.getService();
        try {
            return h == null ? List.of() : h.unmonitoredRooms();
        } catch (RuntimeException e) { // Sensor Health going away
            return List.of();
        }
    }

    @Override
    public void close() {
        health.close();
    }
}

package org.tinysep.runtime.internal.directory;

import java.util.List;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;

/**
 * Writes the device manager's own event-log entries: drivers added and removed, devices created and removed.
 * The origin is always the driver's or device's UID.
 */
final class Announcer {

    private final EventLog log;

    Announcer(EventLog log) {
        this.log = log;
    }

    void driverAdded(DriverRecord d) {
        log.record(EventKind.DRIVER_ADDED, d.uid(),
                "driver " + d.name() + " added (bundle " + d.bundleId() + " " + d.bundleName() + ")");
    }

    void driverRemoved(DriverRecord d) {
        log.record(EventKind.DRIVER_REMOVED, d.uid(), "driver " + d.name() + " removed");
    }

    void deviceCreated(DeviceRecord d, List<String> interfaces) {
        log.record(EventKind.DEVICE_CREATED, d.uid(), d.type() + " \"" + d.name() + "\" created; node types: "
                + list(d.node().types()) + (interfaces.isEmpty() ? "" : "; provides: " + list(interfaces)));
    }

    void deviceRemoved(DeviceRecord d) {
        log.record(EventKind.DEVICE_REMOVED, d.uid(), d.type() + " \"" + d.name() + "\" removed");
    }

    void problem(String origin, String message) {
        log.record(EventKind.PROBLEM, origin, message);
    }

    private static String list(List<String> items) {
        return items.isEmpty() ? "-" : String.join(", ", items);
    }
}

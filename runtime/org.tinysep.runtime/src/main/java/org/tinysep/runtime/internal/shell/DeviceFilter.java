package org.tinysep.runtime.internal.shell;

import java.util.List;
import java.util.Locale;
import org.tinysep.runtime.internal.directory.DeviceView;

/**
 * Which devices {@code devices <filter>} shows: those whose UID starts with the filter, whose node address or
 * driver (or type) is the filter, or whose name contains it, ignoring case. E.g. {@code devices 2.1} shows the bus
 * device and the abstraction devices of node 2.1.
 */
final class DeviceFilter {

    private DeviceFilter() {
    }

    /** @throws IllegalArgumentException when no device matches, naming the filter */
    static List<DeviceView> apply(List<DeviceView> devices, String filter) {
        String q = filter == null ? "" : filter.strip();
        if (q.isEmpty()) {
            return devices;
        }
        String lower = q.toLowerCase(Locale.ROOT);
        List<DeviceView> out = devices.stream().filter(d -> d.uid().startsWith(q) || d.node().address().equals(q)
                || d.driverName().equalsIgnoreCase(q) || d.type().equalsIgnoreCase(q)
                || d.name().toLowerCase(Locale.ROOT).contains(lower)).toList();
        if (out.isEmpty()) {
            throw new IllegalArgumentException(noMatch(q));
        }
        return out;
    }

    /** @return the one-line answer when a device reference matches nothing */
    static String noMatch(String ref) {
        return "no device matches '" + ref + "' (give a UID or its first characters, a node address such as 1.4,"
                + " a driver name or part of a device name; tinysep:devices lists them)";
    }
}

package org.tinysep.itests;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;

/**
 * The device graph as a set of lines, read from the service registry: {@code Type@node} for every device and
 * {@code Type@node <- Interface of Type@node} for every connection (marked {@code (optional)} when not vital).
 * Comparing whole sets makes a test fail on any missing or extra device or connection.
 */
public final class Topology {

    private Topology() {
    }

    public static Set<String> of(BundleContext context) {
        Map<String, String> labels = new HashMap<>();
        List<Device> devices = new ArrayList<>();
        for (ServiceReference<Device> ref : references(context)) {
            Device d = context.getService(ref);
            if (d == null) {
                continue;
            }
            Object node = ref.getProperty(DeviceProperties.NODE_ADDRESS);
            labels.put(d.uid(), d.type() + (node == null ? "" : "@" + node));
            devices.add(d);
            context.ungetService(ref);
        }
        Set<String> lines = new TreeSet<>();
        for (Device d : devices) {
            String label = labels.get(d.uid());
            lines.add(label);
            for (ConnectionInfo c : d.connections()) {
                lines.add(label + " <- " + c.interfaceName() + " of "
                        + labels.getOrDefault(c.providerDeviceUid(), "unregistered " + c.providerDeviceUid())
                        + (c.vital() ? "" : " (optional)"));
            }
        }
        return lines;
    }

    /** @return the UID of the device of that type at that node address (node may be null) */
    public static String uid(BundleContext context, String type, String node) {
        for (ServiceReference<Device> ref : references(context)) {
            Object n = ref.getProperty(DeviceProperties.NODE_ADDRESS);
            if (type.equals(ref.getProperty(DeviceProperties.DEVICE_TYPE)) && (node == null || node.equals(n))) {
                return (String) ref.getProperty(DeviceProperties.DEVICE_UID);
            }
        }
        throw new AssertionError("no device " + type + "@" + node + " in " + of(context));
    }

    private static List<ServiceReference<Device>> references(BundleContext context) {
        try {
            return new ArrayList<>(context.getServiceReferences(Device.class, null));
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}

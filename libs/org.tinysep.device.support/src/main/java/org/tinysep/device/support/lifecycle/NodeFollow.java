package org.tinysep.device.support.lifecycle;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.device.support.health.HealthWords;

/**
 * A device follows its bus node: while the bus device it is connected to (a provider that is a
 * {@link Device} and a {@link NodeHealthSource}: the bus radio's device for its node address) is OFFLINE, the
 * device reports OFFLINE too, with the reason in plain words. Computed when the status is read, so the device
 * writes no STATUS entry of its own: the bus device's entry already tells when the node went silent.
 */
final class NodeFollow {

    /** The bus devices this device is connected to, by their UID. */
    private final Map<String, Device> nodes = new ConcurrentHashMap<>();

    /** Remembers {@code provider} when it is a bus device; other providers are not followed. */
    void connected(Object provider) {
        if (provider instanceof Device d && provider instanceof NodeHealthSource) {
            nodes.put(d.uid(), d);
        }
    }

    /** Forgets a provider device that went. */
    void gone(String providerUid) {
        nodes.remove(providerUid);
    }

    void clear() {
        nodes.clear();
    }

    /** @return {@code own}, or OFFLINE with the reason when a followed bus device is OFFLINE */
    DeviceStatus apply(DeviceStatus own) {
        for (Device node : nodes.values()) {
            DeviceStatus bus;
            try {
                bus = node.status();
            } catch (RuntimeException going) { // a bus device being removed: its removal drops the connection
                continue;
            }
            if (bus.state() == DeviceStatus.State.OFFLINE) {
                return new DeviceStatus(DeviceStatus.State.OFFLINE, reason(node, bus), bus.since());
            }
        }
        return own;
    }

    private static String reason(Device node, DeviceStatus bus) {
        NodeHealth h = ((NodeHealthSource) node).health();
        String words = "its radio node " + h.nodeAddress();
        if (h.silentSince() != null) {
            words += " has been silent since " + HealthWords.time(h.silentSince()) + " (a report was promised every "
                    + HealthWords.span(h.reportInterval()) + ")";
        } else {
            words += " is OFFLINE" + (bus.detail().isEmpty() ? "" : ": " + bus.detail());
        }
        return words + "; this device is OFFLINE with it until the node is heard again (bus device " + node.uid()
                + ")";
    }
}

package org.tinysep.device.support.lifecycle;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Which of a driver's devices are connected to which provider device: when a provider goes, its
 * driver asks only those devices, instead of reading every device's connections (n devices and n providers going
 * made a stop cost n²). Kept by {@link DeviceRegistration} as connections are made and dropped.
 */
final class ConsumerIndex {

    private final Map<String, Set<String>> consumers = new HashMap<>();

    synchronized void connected(String providerUid, String deviceUid) {
        consumers.computeIfAbsent(providerUid, p -> new LinkedHashSet<>(2)).add(deviceUid);
    }

    synchronized void disconnected(String providerUid, String deviceUid) {
        Set<String> devices = consumers.get(providerUid);
        if (devices != null && devices.remove(deviceUid) && devices.isEmpty()) {
            consumers.remove(providerUid);
        }
    }

    /** @return the UIDs of the devices connected to that provider, in the order they connected */
    synchronized List<String> consumersOf(String providerUid) {
        Set<String> devices = consumers.get(providerUid);
        return devices == null ? List.of() : new ArrayList<>(devices);
    }
}

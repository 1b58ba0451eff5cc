package org.tinysep.runtime.internal.directory;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.device.Device;

/**
 * A tracked service carrying a device UID: one or more provided interfaces of that device.
 *
 * @param serviceId  the service.id of its registration
 * @param deviceUid  the device it belongs to
 * @param interfaces simple names of its objectClass entries, without {@code Device} itself
 */
public record ProviderRecord(long serviceId, String deviceUid, List<String> interfaces) {

    public ProviderRecord {
        interfaces = List.copyOf(interfaces);
    }

    /** @param objectClass the fully qualified names the service is registered under */
    static ProviderRecord of(long serviceId, String deviceUid, String[] objectClass) {
        List<String> names = new ArrayList<>();
        for (String fqcn : objectClass == null ? new String[0] : objectClass) {
            if (!Device.class.getName().equals(fqcn)) {
                names.add(fqcn.substring(fqcn.lastIndexOf('.') + 1));
            }
        }
        return new ProviderRecord(serviceId, deviceUid, names);
    }
}

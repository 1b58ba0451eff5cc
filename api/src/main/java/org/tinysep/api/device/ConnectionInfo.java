package org.tinysep.api.device;

import java.util.Objects;

/**
 * One connection a device holds as a consumer.
 *
 * @param interfaceName    the simple name of the consumed interface, e.g. {@code MovementProvider}
 * @param providerDeviceUid the UID of the device that provides it
 * @param vital            whether losing it makes the consumer remove itself (thesis 3.3)
 */
public record ConnectionInfo(String interfaceName, String providerDeviceUid, boolean vital) {

    public ConnectionInfo {
        Objects.requireNonNull(interfaceName, "interfaceName");
        Objects.requireNonNull(providerDeviceUid, "providerDeviceUid");
    }
}

package org.tinysep.device.support.lifecycle;

import java.nio.charset.StandardCharsets;
import java.util.UUID;

/**
 * Stable UIDs: a driver's or device's UID is derived from what identifies it (driver name, node address), so the
 * same node gets the same device UID after a restart or a driver update.
 */
public final class Uids {

    private Uids() {
    }

    /** @return a name-based (type 3) UUID of the parts joined by '/' */
    public static String of(String... parts) {
        return UUID.nameUUIDFromBytes(String.join("/", parts).getBytes(StandardCharsets.UTF_8)).toString();
    }

    /** @return the UID of the driver with this name */
    public static String driver(String driverName) {
        return of("tinysep-driver", driverName);
    }
}

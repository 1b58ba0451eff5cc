package org.tinysep.api.device;

import java.util.List;
import org.osgi.annotation.versioning.ConsumerType;

/**
 * A TinySEP driver (thesis Table 4.1): it decides, on interfaces appearing, whether to create devices, and
 * manages them. Registered as an OSGi service (typically a Declarative Services component) with
 * {@link DeviceProperties#DRIVER_UID} and {@link DeviceProperties#DRIVER_NAME}.
 */
@ConsumerType
public interface Driver {

    /** @return the driver UID; stable across restarts */
    String uid();

    /** @return the driver name shown to the user (e.g. {@code AmicaMovement}) */
    String name();

    /** @return the devices this driver currently has, in creation order */
    List<Device> devices();

    /** @return driver-level figures and settings (e.g. bound port, rejected-packet counters) */
    List<Parameter> parameters();

    /**
     * Removes one of this driver's devices; its services are unregistered and the removal announced.
     *
     * @return whether the device was one of this driver's
     */
    boolean removeDevice(String deviceUid);
}

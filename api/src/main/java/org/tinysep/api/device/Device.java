package org.tinysep.api.device;

import java.util.List;
import org.osgi.annotation.versioning.ConsumerType;

/**
 * A TinySEP device (thesis Table 4.2): an object created by a {@link Driver} that provides and consumes
 * interfaces. Registered as an OSGi service with the {@link DeviceProperties}.
 * <p>
 * Creation and connection logic of the thesis ({@code createDevice}, {@code connectToDevice},
 * {@code newInterfaceFound}) live in the implementing bundle; the manager-facing part is what remains here.
 */
@ConsumerType
public interface Device {

    /** @return the device UID, unique and stable for the life of the device */
    String uid();

    /** @return the device type, the same for every device of one driver (e.g. {@code AmicaMovement}) */
    String type();

    /** @return the UID of the driver that created this device */
    String driverUid();

    /** @return a human-readable name; by default derived from the type and the hardware address */
    String name();

    /** @return the current status; trouble is reported here rather than as exceptions */
    DeviceStatus status();

    /** @return the configuration parameters in display order (thesis getDeviceParameters) */
    List<Parameter> parameters();

    /**
     * Changes one writable parameter (thesis setDeviceParameters).
     *
     * @throws IllegalArgumentException with a message a user can act on, if the key is unknown, read-only or
     *                                  the value invalid; the device is then unchanged
     */
    void setParameter(String key, String value);

    /** @return the user-invocable functions (thesis getAllFunctions); empty when there are none */
    List<DeviceFunction> functions();

    /**
     * Runs one of {@link #functions()} (thesis loadFunctions).
     *
     * @return a short result text for the user
     * @throws IllegalArgumentException if there is no such function
     */
    String invoke(String function);

    /** @return the interfaces this device currently consumes, one entry per open connection */
    List<ConnectionInfo> connections();
}

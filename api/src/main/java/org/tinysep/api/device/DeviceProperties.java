package org.tinysep.api.device;

/**
 * Service property names published by every {@link Driver}, {@link Device} and {@link Provider} service.
 * Consumers filter on them with {@code ServiceTracker}s, e.g.
 * {@code (&(objectClass=org.tinysep.api.bus.BusRadioAmicaProvider)(tinysep.node.type=movement))}.
 */
public final class DeviceProperties {

    /** UID of the device ({@code String}). On Device and Provider services. */
    public static final String DEVICE_UID = "tinysep.device.uid";
    /** Type of the device ({@code String}), equal to the driver name for most drivers. */
    public static final String DEVICE_TYPE = "tinysep.device.type";
    /** UID of the driver ({@code String}). On Driver, Device and Provider services. */
    public static final String DRIVER_UID = "tinysep.driver.uid";
    /** Name of the driver ({@code String}). */
    public static final String DRIVER_NAME = "tinysep.driver.name";
    /** Node types of the hardware node behind a device ({@code String[]}, values of {@link NodeType}). */
    public static final String NODE_TYPE = "tinysep.node.type";
    /** Hardware address of the node ({@code String}, family-specific form). */
    public static final String NODE_ADDRESS = "tinysep.node.address";
    /** UID of the room the device is in ({@code String}); absent when not yet placed. */
    public static final String ROOM = "tinysep.room";

    private DeviceProperties() {
    }
}

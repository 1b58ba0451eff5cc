package org.tinysep.api.device;

/**
 * Well-known node type names used as values of {@link DeviceProperties#NODE_TYPE}. The set is open: a new
 * vendor may publish other names; consumers ignore names they do not know (thesis 3.5).
 */
public final class NodeType {

    public static final String MOVEMENT = "movement";
    public static final String DOOR = "door";
    public static final String WINDOW = "window";
    public static final String SIMPLE_LIGHT = "simple-light";
    public static final String DIMMABLE_LIGHT = "dimmable-light";
    public static final String HEATER = "heater";
    public static final String SPEAKER = "speaker";
    public static final String PET_COLLAR = "pet-collar";
    public static final String TEMPERATURE = "temperature";
    public static final String LIGHT_SENSOR = "light-sensor";

    private NodeType() {
    }
}

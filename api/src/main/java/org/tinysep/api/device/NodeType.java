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
    /** Presence node: a pressure mat in or under a bed ({@code PresenceKind.BED}). Since 1.1. */
    public static final String PRESENCE_BED = "presence-bed";
    /** Presence node: a pressure mat on a seat or sofa ({@code PresenceKind.SEAT}). Since 1.1. */
    public static final String PRESENCE_SEAT = "presence-seat";
    /** Presence node: a toilet flush ({@code PresenceKind.FLUSH}). Since 1.1. */
    public static final String PRESENCE_FLUSH = "presence-flush";
    /** Presence node: an appliance in use ({@code PresenceKind.APPLIANCE}). Since 1.1. */
    public static final String PRESENCE_APPLIANCE = "presence-appliance";
    /**
     * The common prefix of the presence node types: {@code "presence-"} + the {@code PresenceKind} in lower case.
     * Since 1.1.
     */
    public static final String PRESENCE_PREFIX = "presence-";
    /**
     * Person node: a node worn by one person at the waist or as a pendant, reporting its switches, its
     * movement and the raw acceleration around peaks ({@code org.tinysep.api.sensor.person}). Since 1.2.
     */
    public static final String PERSON = "person";

    private NodeType() {
    }
}

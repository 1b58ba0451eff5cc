package org.tinysep.api.alert;

/** What an alert is about; the kinds differ in urgency. */
public enum AlertKind {
    /** Inactivity Recognition: the person may have collapsed. Repeated and escalated until acknowledged. */
    INACTIVITY("inactivity (the person may need help)"),
    /** A sensor stopped reporting: lower priority, a notice. */
    SENSOR_OFFLINE("sensor offline"),
    /** The platform itself (restarts, full disk, ...). */
    PLATFORM("platform"),
    /** The person pressed and held the help switch of the node they wear: urgent, like INACTIVITY. */
    HELP("help button (the person asked for help)"),
    /** Fall detection saw a fall on the node the person wears: urgent, like INACTIVITY. */
    FALL("fall (the person may have fallen)");

    private final String words;

    AlertKind(String words) {
        this.words = words;
    }

    /**
     * @return what an alert of this kind is about, in the plain words every view of it uses (the caregiver page, the
     *         MQTT bridge, the care centre's board), e.g. {@code "fall (the person may have fallen)"}
     * @since 1.3
     */
    public String words() {
        return words;
    }
}

package org.tinysep.api.alert;

/** What an alert is about; the kinds differ in urgency. */
public enum AlertKind {
    /** Inactivity Recognition: the person may have collapsed. Repeated and escalated until acknowledged. */
    INACTIVITY,
    /** A sensor stopped reporting (issue 12, item 2): lower priority, a notice. */
    SENSOR_OFFLINE,
    /** The platform itself (restarts, full disk, ...). */
    PLATFORM,
    /** The person pressed and held the help switch of the node they wear (issue 26): urgent, like INACTIVITY. */
    HELP,
    /** Fall detection saw a fall on the node the person wears (issue 26): urgent, like INACTIVITY. */
    FALL
}

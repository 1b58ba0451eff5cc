package org.tinysep.api.alert;

/** What an alert is about; the kinds differ in urgency. */
public enum AlertKind {
    /** Inactivity Recognition: the person may have collapsed. Repeated and escalated until acknowledged. */
    INACTIVITY,
    /** A sensor stopped reporting (issue 12, item 2): lower priority, a notice. */
    SENSOR_OFFLINE,
    /** The platform itself (restarts, full disk, ...). */
    PLATFORM
}

package org.tinysep.api.sensor;

/** State of a door or window contact (AmICA reed switch). */
public enum OpenState {
    OPEN,
    CLOSED,
    /** No status received yet. */
    UNKNOWN
}

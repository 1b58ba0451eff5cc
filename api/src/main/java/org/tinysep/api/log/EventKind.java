package org.tinysep.api.log;

/** What an {@link EventEntry} records. */
public enum EventKind {
    DRIVER_ADDED,
    DRIVER_REMOVED,
    DEVICE_CREATED,
    DEVICE_REMOVED,
    CONNECTED,
    DISCONNECTED,
    /** Something a device observed: a door opened, a movement, the flat became occupied. */
    DEVICE_EVENT,
    /** A device or driver changed status (online, offline, error). */
    STATUS,
    /** Input rejected or an operation failed; the detail says why. */
    PROBLEM
}

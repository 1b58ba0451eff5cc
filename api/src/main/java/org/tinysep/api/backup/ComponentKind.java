package org.tinysep.api.backup;

/** What a backup belongs to. */
public enum ComponentKind {
    /** a driver: its own settings */
    DRIVER,
    /** a device of a driver */
    DEVICE
}

package org.tinysep.api.sensor;

/** Whether a door connects the flat with the outside (thesis 3.7). */
public enum DoorKind {
    /** Between the flat and the outside: the one Flat Occupancy watches. */
    OUTER,
    /** Between two rooms. */
    INNER
}

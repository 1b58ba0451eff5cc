package org.tinysep.api.service;

/** Whether someone is in the flat (thesis A.12). */
public enum Occupancy {
    OCCUPIED,
    UNOCCUPIED,
    /** Not yet decided (no evidence since start). */
    UNKNOWN
}

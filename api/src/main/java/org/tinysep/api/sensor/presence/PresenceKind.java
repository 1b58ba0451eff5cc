package org.tinysep.api.sensor.presence;

/** What a presence sensor observes. */
public enum PresenceKind {
    /** A pressure mat in or under a bed: ON while someone lies in bed. */
    BED,
    /** A pressure mat on a seat or sofa: ON while someone sits there. */
    SEAT,
    /** A toilet flush: ON while it is used. */
    FLUSH,
    /** An appliance (cooker, kettle, microwave, toaster, TV) in use: ON while it runs. */
    APPLIANCE,
    /** Any other sign of use. */
    OTHER;

    /**
     * @return whether ON means that a person is at the sensor right now (a bed or seat mat): the flat is occupied
     *         for as long as it stays ON. An appliance may run with nobody near it; a flush is a moment.
     */
    public boolean holdsPerson() {
        return this == BED || this == SEAT;
    }
}

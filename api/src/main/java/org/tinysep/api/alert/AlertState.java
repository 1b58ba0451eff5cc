package org.tinysep.api.alert;

/** Where an alert stands. Only {@link #OPEN} alerts are repeated and escalated. */
public enum AlertState {
    /** Raised and nobody has acknowledged it yet. */
    OPEN,
    /** Somebody said they take care of it ({@link AlertService#acknowledge}). */
    ACKNOWLEDGED,
    /** Its cause ended by itself (the person is active again); an "all clear" followed if it was still open. */
    CLEARED
}

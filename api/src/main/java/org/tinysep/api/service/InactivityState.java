package org.tinysep.api.service;

/** State of inactivity recognition (thesis A.16). */
public enum InactivityState {
    /** Nobody home (or no evidence): not watching. */
    NOT_WATCHING,
    /** Someone is home and activity is recent enough. */
    WATCHING,
    /** The room's inactivity limit expired: help was called. */
    ALERT
}

package org.tinysep.api.sensor.person;

/** What happened to a switch. */
public enum ButtonAction {
    PRESSED,
    RELEASED
}

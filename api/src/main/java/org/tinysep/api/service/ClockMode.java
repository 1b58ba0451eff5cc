package org.tinysep.api.service;

/** Where the Time Controller's clock comes from (thesis 4.4.3.4). */
public enum ClockMode {
    /** The system clock. */
    REAL,
    /** Driven from outside in lock-step by a time synchroniser (thesis 5.4.3). */
    EXTERNAL
}

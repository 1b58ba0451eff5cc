package org.tinysep.drivers.internal;

/** The {@code STATUS} values the platform writes into the drivers list. */
final class Status {

    /** Running. */
    static final String ACTIVE = "ACTIVE";
    /** Being started, or lazily activated. */
    static final String STARTING = "STARTING";
    /** Installed and resolved but not running (e.g. its driver was removed from the shell). */
    static final String STOPPED = "STOPPED";
    /** Installed, waiting for the framework to reach the application start level. */
    static final String INSTALLED = "INSTALLED";
    /** {@code ENABLED} is false: not started (and not installed at start-up). */
    static final String DISABLED = "DISABLED";
    /** A new entry the platform has not loaded yet ({@code tinysep:drivers reload}). */
    static final String PENDING = "PENDING";

    private Status() {
    }

    /** @return {@code FAILED: <reason>} */
    static String failed(String reason) {
        return "FAILED: " + reason;
    }

    /** @return {@code MISSING: <file>} */
    static String missing(String file) {
        return "MISSING: " + file;
    }
}

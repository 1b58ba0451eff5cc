package org.tinysep.drivers.internal;

/**
 * One application of the drivers list.
 *
 * @param location     {@code FILE_PATH}: a path relative to {@code tinysep.home}, an absolute path, or a URL
 * @param symbolicName {@code FULL_NAME}: the bundle's symbolic name; empty until the bundle was first installed
 * @param enabled      whether the platform should run it
 * @param status       what the platform last saw ({@link Status}); never read as an instruction
 */
record DriverEntry(String location, String symbolicName, boolean enabled, String status) {

    DriverEntry {
        location = location == null ? "" : location.strip();
        symbolicName = symbolicName == null ? "" : symbolicName.strip();
        status = status == null ? "" : status.strip();
    }

    /** @return the symbolic name when known, else the location: how entries are matched across loads */
    String key() {
        return symbolicName.isEmpty() ? location : symbolicName;
    }

    DriverEntry withStatus(String newStatus) {
        return new DriverEntry(location, symbolicName, enabled, newStatus);
    }

    DriverEntry withEnabled(boolean on) {
        return new DriverEntry(location, symbolicName, on, status);
    }

    DriverEntry withSymbolicName(String bsn) {
        return new DriverEntry(location, bsn, enabled, status);
    }
}

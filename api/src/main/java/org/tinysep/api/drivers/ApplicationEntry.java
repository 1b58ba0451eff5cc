package org.tinysep.api.drivers;

import java.util.Objects;

/**
 * One application of the drivers list.
 *
 * @param application  how the list names it: its bundle symbolic name once known, else its location
 * @param symbolicName the bundle's symbolic name; empty until the bundle was first installed
 * @param location     where the platform loads it from: a path relative to {@code tinysep.home}, an absolute path or
 *                     a URL
 * @param enabled      whether the platform should run it
 * @param status       what the platform last saw, in words (e.g. {@code ACTIVE}, {@code not installed: …})
 */
public record ApplicationEntry(String application, String symbolicName, String location, boolean enabled,
        String status) {

    public ApplicationEntry {
        Objects.requireNonNull(application, "application");
        symbolicName = symbolicName == null ? "" : symbolicName;
        location = location == null ? "" : location;
        status = status == null ? "" : status;
    }
}

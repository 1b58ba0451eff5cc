package org.tinysep.drivers.internal;

/**
 * What the drivers list needs from the framework, by bundle id (a seam: {@link OsgiBundles} in the framework, a fake
 * in unit tests). Failures are thrown with a one-line message.
 */
interface Bundles {

    /** @return the id of an installed bundle with this symbolic name (if not empty) or location, else -1 */
    long find(String symbolicName, String location);

    /** Installs {@code location} at {@code startLevel}. @return its id */
    long install(String location, int startLevel) throws Exception;

    /** @return the bundle's symbolic name ("" when gone) */
    String symbolicName(long id);

    /** Starts the bundle persistently (at once, or when the framework reaches its start level). */
    void start(long id) throws Exception;

    /** Stops the bundle persistently. */
    void stop(long id) throws Exception;

    /** Uninstalls the bundle and refreshes it, so only its dependents are re-wired. */
    void uninstall(long id) throws Exception;

    /** @return whether the bundle is ACTIVE or STARTING */
    boolean isRunning(long id);

    /** @return a {@link Status} text for an enabled entry's bundle ("" when the bundle is gone) */
    String status(long id);
}

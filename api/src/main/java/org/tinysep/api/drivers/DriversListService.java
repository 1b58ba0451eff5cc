package org.tinysep.api.drivers;

import java.util.List;
import org.osgi.annotation.versioning.ProviderType;

/**
 * The drivers list: the applications the platform runs and the operator's changes to them. Every change is applied
 * at once and kept in the list file, so it holds across restarts. Methods that change the list answer with what
 * changed, one line per change, in plain words. Errors are {@link IllegalArgumentException} (the request names
 * something the list does not have) or {@link IllegalStateException} (the list file cannot be used), each with a
 * message for the operator.
 */
@ProviderType
public interface DriversListService {

    /** @return the list file, as a path */
    String file();

    /** @return the applications with their live status, in the list's order */
    List<ApplicationEntry> applications();

    /** Re-reads the list file and applies it. @return one line per change, or empty when nothing changed */
    List<String> reload();

    /**
     * Switches one application on or off, in the list too.
     *
     * @param application its bundle symbolic name (or location)
     * @return one line per change, or one line saying it already was so
     */
    List<String> setEnabled(String application, boolean enabled);

    /**
     * Loads the application from another jar from the next start on (the running bundle is not touched).
     *
     * @param symbolicName the application's bundle symbolic name; the jar must be a bundle of that name
     * @param file         the jar: a path (relative to {@code tinysep.home}) or a {@code file:} URL
     * @return what changed, in words
     */
    String use(String symbolicName, String file);
}

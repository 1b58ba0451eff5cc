package org.tinysep.runtime.internal.backup;

import java.nio.file.Path;
import org.osgi.framework.BundleContext;

/**
 * Resolves a state folder by the platform convention: the configured path when set, else
 * {@code ${tinysep.var}/<name>}, else {@code ${tinysep.home}/var/<name>}, else the bundle's data area.
 */
final class StateFolder {

    static final String VAR = "tinysep.var";
    static final String HOME = "tinysep.home";

    private StateFolder() {
    }

    static Path resolve(String configured, BundleContext context, String name) {
        if (configured != null && !configured.isBlank()) {
            return Path.of(configured.strip()).toAbsolutePath();
        }
        String var = context.getProperty(VAR);
        if (var != null && !var.isBlank()) {
            return Path.of(var.strip(), name).toAbsolutePath();
        }
        String home = context.getProperty(HOME);
        if (home != null && !home.isBlank()) {
            return Path.of(home.strip(), "var", name).toAbsolutePath();
        }
        return context.getDataFile(name).toPath().toAbsolutePath();
    }
}

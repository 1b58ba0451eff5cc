package org.tinysep.device.support.files;

import java.io.File;
import java.nio.file.Path;
import java.util.Optional;
import org.osgi.framework.BundleContext;

/**
 * Where a component keeps its state files (docs/runtime-changes.md): a configured path wins, else
 * {@code ${tinysep.var}/<name>}, else {@code ${tinysep.home}/var/<name>}; with neither framework property (e.g. a
 * test framework) the caller picks its own fallback. Never under the source tree or {@code target/}.
 */
public final class StateFolder {

    /** Framework property: the state folder; the launcher sets it (default {@code ${tinysep.home}/var}). */
    public static final String VAR = "tinysep.var";
    /** Framework property: the distribution folder. */
    public static final String HOME = "tinysep.home";

    private StateFolder() {
    }

    /**
     * @return {@link #resolve(String, BundleContext, String)}, else {@code name} in the bundle's data area (Pax Exam
     *         and bare frameworks have neither property); null only without a context or data area
     */
    public static Path resolveOrDataArea(String configured, BundleContext context, String name) {
        Optional<Path> path = context == null ? resolve(configured, null, null, name)
                : resolve(configured, context, name);
        if (path.isPresent() || context == null) {
            return path.orElse(null);
        }
        File data = context.getDataFile(name);
        return data == null ? null : data.toPath().toAbsolutePath();
    }

    /** @return {@link #resolve(String, String, String, String)} with the framework properties of {@code context} */
    public static Optional<Path> resolve(String configured, BundleContext context, String name) {
        return resolve(configured, context.getProperty(VAR), context.getProperty(HOME), name);
    }

    /**
     * @param configured a path set in the component's configuration, or empty/null
     * @param var        the {@value #VAR} property, or null
     * @param home       the {@value #HOME} property, or null
     * @param name       the file or folder name inside the state folder
     * @return the absolute path, or empty when neither a configured path nor either property is set
     */
    public static Optional<Path> resolve(String configured, String var, String home, String name) {
        if (hasText(configured)) {
            return Optional.of(Path.of(configured.strip()).toAbsolutePath());
        }
        if (hasText(var)) {
            return Optional.of(Path.of(var.strip(), name).toAbsolutePath());
        }
        if (hasText(home)) {
            return Optional.of(Path.of(home.strip(), "var", name).toAbsolutePath());
        }
        return Optional.empty();
    }

    private static boolean hasText(String s) {
        return s != null && !s.isBlank();
    }
}

package org.tinysep.launcher;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.util.jar.Manifest;
import org.slf4j.LoggerFactory;

/**
 * The SLF4J packages the system bundle exports to the bundles: the launcher's own slf4j-api, with the
 * versions and {@code uses} its jar's {@code Export-Package} header gives, so a bundle importing
 * {@code org.slf4j;version="[2.0,3)"} wires to the one SLF4J the launcher configured ({@link LoggingDefaults}).
 */
final class Slf4jExports {

    /** Used when the manifest cannot be read (classes run from a folder, not the jar). */
    static final String FALLBACK = "org.slf4j;version=2.0.20,org.slf4j.event;version=2.0.20,"
            + "org.slf4j.helpers;version=2.0.20,org.slf4j.spi;version=2.0.20";

    private Slf4jExports() {
    }

    /** @return the {@code Export-Package} header of the slf4j-api jar on the class path */
    static String header() {
        URL location = LoggerFactory.class.getProtectionDomain().getCodeSource() == null ? null
                : LoggerFactory.class.getProtectionDomain().getCodeSource().getLocation();
        if (location == null) {
            return FALLBACK;
        }
        try {
            URL manifest = new URL("jar:" + location + "!/META-INF/MANIFEST.MF");
            try (InputStream in = manifest.openStream()) {
                String exports = new Manifest(in).getMainAttributes().getValue("Export-Package");
                return exports == null || !exports.contains("org.slf4j") ? FALLBACK : exports;
            }
        } catch (IOException | RuntimeException e) {
            return FALLBACK;
        }
    }
}

package org.tinysep.gradle;

import aQute.bnd.osgi.Builder;
import aQute.bnd.osgi.Jar;
import java.io.File;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Makes a module's bundle the way the Maven build's bnd-maven-plugin does: the compiled classes and resources, the
 * instructions of the module's bnd.bnd, and the same defaults (Bundle-SymbolicName = artifactId, Bundle-Name and
 * Bundle-Description from the pom, Bundle-Version from the pom's version with a SNAPSHOT qualifier of minute
 * resolution). bnd itself (bndlib, the same version as the Maven plugin) computes imports, exports and DS components.
 */
public final class BndBuild {
    private BndBuild() {
    }

    /**
     * Builds the bundle into {@code out} from {@code contents} (classes and resources folders), with the compile
     * class path for -conditionalpackage, -includeresource and import versions. Returns bnd's warnings; throws with bnd's errors (the build fails).
     */
    public static List<String> build(Pom pom, File moduleDir, List<File> contents, List<File> classpath,
            Map<String, String> jarPluginHeaders, File out) throws Exception {
        try (Builder b = new Builder(); Jar jar = new Jar(pom.artifactId)) {
            b.setBase(moduleDir);
            File bnd = new File(moduleDir, "bnd.bnd");
            if (bnd.isFile()) {
                b.setProperties(bnd);
            }
            b.setProperty("project.version", pom.version);
            b.setProperty("project.artifactId", pom.artifactId);
            b.setProperty("project.groupId", pom.groupId);
            defaultTo(b, "Bundle-SymbolicName", pom.artifactId);
            defaultTo(b, "Bundle-Name", pom.name);
            if (!pom.description.isEmpty()) {
                defaultTo(b, "Bundle-Description", pom.description);
            }
            defaultTo(b, "Bundle-Version", osgiVersion(pom.version));
            // what the pom's maven-jar-plugin adds to bnd's manifest (Main-Class, Class-Path)
            jarPluginHeaders.forEach(b::setProperty);
            for (File f : contents) {
                if (f.exists()) {
                    jar.addAll(new Jar(f));
                }
            }
            b.setJar(jar);
            List<File> cp = new ArrayList<>();
            for (File f : classpath) {
                if (f.exists()) {
                    cp.add(f);
                }
            }
            b.setClasspath(cp.toArray(new File[0]));
            Jar built = b.build();
            if (!b.getErrors().isEmpty()) {
                throw new IllegalStateException("bnd failed for " + pom.artifactId + ": " + b.getErrors());
            }
            out.getParentFile().mkdirs();
            built.write(out);
            return new ArrayList<>(b.getWarnings());
        }
    }

    private static void defaultTo(Builder b, String key, String value) {
        if (b.getProperty(key) == null) {
            b.setProperty(key, value);
        }
    }

    /** 0.1.0-SNAPSHOT becomes 0.1.0.202611290312 (UTC minutes), as the Maven plugin makes it; 1.2.3 stays. */
    static String osgiVersion(String mavenVersion) {
        if (mavenVersion.endsWith("-SNAPSHOT")) {
            String stamp = ZonedDateTime.now(ZoneOffset.UTC).format(DateTimeFormatter.ofPattern("yyyyMMddHHmm"));
            return mavenVersion.substring(0, mavenVersion.length() - "-SNAPSHOT".length()) + "." + stamp;
        }
        return mavenVersion.replace('-', '.');
    }
}

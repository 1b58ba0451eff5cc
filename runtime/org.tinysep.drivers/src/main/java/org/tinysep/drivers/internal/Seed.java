package org.tinysep.drivers.internal;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.jar.JarFile;
import java.util.jar.Manifest;
import java.util.stream.Stream;
import org.osgi.framework.Version;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The list at start-up: the file, else (missing or unusable) one enabled entry per bundle jar of the distribution's
 * applications folder.
 */
final class Seed {

    private static final Logger LOG = LoggerFactory.getLogger(Seed.class);

    private Seed() {
    }

    /**
     * @return the entries of {@code file} (re-pointed to a new build's jars, {@link #repoint}), or when it is missing
     *         or broken (moved aside), the seeded list
     */
    static List<DriverEntry> startList(DriversFile file, Path seedFolder, Locations locations, Report report) {
        if (file.exists()) {
            try {
                return repoint(file.read(Instant.now()), seedFolder, locations);
            } catch (MalformedDriversException | IOException e) {
                report.problem("unusable: " + e.getMessage() + "; starting from the applications folder "
                        + seedFolder);
            }
        }
        try {
            List<DriverEntry> seeded = fromFolder(seedFolder, locations);
            LOG.info("Drivers list {} created from {} ({} applications)", file.path(), seedFolder, seeded.size());
            return seeded;
        } catch (IOException e) {
            LOG.error("Cannot list {}: {}; the drivers list starts empty", seedFolder, e.getMessage());
            return List.of();
        }
    }

    /**
     * @param appsDir   {@code ${tinysep.home}/bundles/5-apps}; a missing folder gives an empty list
     * @param locations turns each jar into its {@code FILE_PATH} (relative to home)
     * @return the entries in file-name order (the launcher's old install order)
     */
    static List<DriverEntry> fromFolder(Path appsDir, Locations locations) throws IOException {
        List<DriverEntry> entries = new ArrayList<>();
        if (appsDir == null || !Files.isDirectory(appsDir)) {
            return entries;
        }
        try (Stream<Path> files = Files.list(appsDir)) {
            for (Path jar : files.filter(f -> f.getFileName().toString().endsWith(".jar")).sorted().toList()) {
                String bsn = symbolicName(jar);
                if (bsn != null) {
                    entries.add(new DriverEntry(locations.filePath(jar.toUri().toString()), bsn, true, ""));
                }
            }
        }
        return entries;
    }

    /**
     * Follows a new build of the distribution: an entry whose file is missing gets the jar of the same symbolic name
     * in {@code appsDir}, if there is one (e.g. {@code x-0.1.0.jar} became {@code x-0.2.0.jar}). An entry pointing
     * outside {@code appsDir} (an update uploaded in the web console, a shell install) keeps its file unless
     * {@code appsDir} holds a higher Bundle-Version of it: a newer distribution is never run with an older copy.
     *
     * @return the entries, re-pointed where needed
     */
    static List<DriverEntry> repoint(List<DriverEntry> entries, Path appsDir, Locations locations) {
        if (appsDir == null || !Files.isDirectory(appsDir)) {
            return entries;
        }
        List<DriverEntry> current;
        try {
            current = fromFolder(appsDir, locations);
        } catch (IOException e) {
            return entries;
        }
        List<DriverEntry> out = new ArrayList<>();
        for (DriverEntry e : entries) {
            Optional<Path> file = locations.file(e.location());
            boolean missing = file.map(f -> !Files.isRegularFile(f)).orElse(false);
            DriverEntry now = e.symbolicName().isEmpty() ? null : current.stream()
                    .filter(c -> c.symbolicName().equals(e.symbolicName())).findFirst().orElse(null);
            if (now != null && missing) {
                LOG.info("Drivers list: {} moved from {} to {}", e.key(), e.location(), now.location());
                out.add(new DriverEntry(now.location(), e.symbolicName(), e.enabled(), e.status()));
            } else if (now != null && file.isPresent() && !file.get().startsWith(appsDir.toAbsolutePath().normalize())
                    && newer(locations.file(now.location()).orElseThrow(), file.get())) {
                LOG.warn("Drivers list: {}: the distribution's {} ({}) is newer than {} ({}), which an upload or a"
                        + " shell install had put in the list; the distribution's is used from now on (the older"
                        + " file is left where it is)", e.key(), version(locations.file(now.location()).orElseThrow()),
                        now.location(), version(file.get()), e.location());
                out.add(new DriverEntry(now.location(), e.symbolicName(), e.enabled(), e.status()));
            } else {
                out.add(e);
            }
        }
        return out;
    }

    /** @return whether jar {@code a}'s Bundle-Version is higher than jar {@code b}'s (unreadable: not newer) */
    static boolean newer(Path a, Path b) {
        Version va = version(a);
        Version vb = version(b);
        return va != null && vb != null && va.compareTo(vb) > 0;
    }

    /** @return the jar's Bundle-Version, or null when it is unreadable */
    static Version version(Path jar) {
        try (JarFile f = new JarFile(jar.toFile())) {
            Manifest m = f.getManifest();
            String v = m == null ? null : m.getMainAttributes().getValue("Bundle-Version");
            return v == null ? Version.emptyVersion : Version.parseVersion(v.strip());
        } catch (IOException | IllegalArgumentException e) {
            return null;
        }
    }

    /** @return the jar's Bundle-SymbolicName without directives, or null when it is no bundle */
    static String symbolicName(Path jar) {
        try (JarFile f = new JarFile(jar.toFile())) {
            Manifest m = f.getManifest();
            String bsn = m == null ? null : m.getMainAttributes().getValue("Bundle-SymbolicName");
            return bsn == null ? null : bsn.split(";")[0].strip();
        } catch (IOException e) {
            return null;
        }
    }
}

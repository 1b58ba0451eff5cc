package org.tinysep.drivers.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class LocationsTest {

    private static final Path HOME = Path.of("/opt/tinysep");
    private final Locations locations = new Locations(HOME);

    @TempDir
    Path dir;

    @Test
    void pathsAreRelativeToHomeAndUrlsStayAsTheyAre() {
        assertEquals("file:///opt/tinysep/bundles/5-apps/a.jar", locations.url("bundles/5-apps/a.jar"));
        assertEquals("file:///srv/b.jar", locations.url("/srv/b.jar"));
        assertEquals("https://example.org/y.jar", locations.url("https://example.org/y.jar"));
        assertTrue(locations.refusal("mvn:org.x/y/1.0").isPresent(), "only file: and https: are installed");
        assertEquals(Path.of("/srv/b.jar"), locations.file("file:/srv/b.jar").orElseThrow());
        assertTrue(locations.file("http://example.org/c.jar").isEmpty());
    }

    @Test
    void installedLocationsUnderHomeBecomeRelative() {
        assertEquals("bundles/5-apps/a.jar", locations.filePath("file:/opt/tinysep/bundles/5-apps/a.jar"));
        assertEquals("bundles/5-apps/a.jar", locations.filePath("file:///opt/tinysep/bundles/5-apps/a.jar"));
        assertEquals("file:/srv/b.jar", locations.filePath("file:/srv/b.jar"));
        assertTrue(locations.isUnder("file:/opt/tinysep/deploy/x.jar", HOME.resolve("deploy")));
        assertFalse(locations.isUnder("file:/opt/tinysep/bundles/x.jar", HOME.resolve("deploy")));
        assertFalse(locations.isUnder("file:/opt/tinysep/deploy/x.jar", null));
    }

    @Test
    void seedListsTheBundlesOfTheAppsFolderInNameOrder() throws Exception {
        Path apps = Files.createDirectories(dir.resolve("bundles/5-apps"));
        jar(apps.resolve("b-1.0.jar"), "org.b;singleton:=true");
        jar(apps.resolve("a-1.0.jar"), "org.a");
        jar(apps.resolve("plain.jar"), null);
        Files.writeString(apps.resolve("notes.txt"), "x");
        List<DriverEntry> seeded = Seed.fromFolder(apps, new Locations(dir));
        assertEquals(List.of(new DriverEntry("bundles/5-apps/a-1.0.jar", "org.a", true, ""),
                new DriverEntry("bundles/5-apps/b-1.0.jar", "org.b", true, "")), seeded);
        assertTrue(Seed.fromFolder(dir.resolve("none"), new Locations(dir)).isEmpty());
    }

    @Test
    void entriesFollowANewBuildOfTheDistribution() throws Exception {
        Path apps = Files.createDirectories(dir.resolve("bundles/5-apps"));
        jar(apps.resolve("door-0.2.0.jar"), "org.door");
        Locations l = new Locations(dir);
        List<DriverEntry> old = List.of(new DriverEntry("bundles/5-apps/door-0.1.0.jar", "org.door", false, "DISABLED"),
                new DriverEntry("bundles/5-apps/gone-0.1.0.jar", "org.gone", true, ""),
                new DriverEntry("/elsewhere/mine.jar", "", true, ""));
        assertEquals(List.of(new DriverEntry("bundles/5-apps/door-0.2.0.jar", "org.door", false, "DISABLED"),
                old.get(1), old.get(2)), Seed.repoint(old, apps, l), "only a missing file with a successor moves");
    }

    private static void jar(Path path, String bsn) throws Exception {
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        if (bsn != null) {
            m.getMainAttributes().putValue("Bundle-SymbolicName", bsn);
        }
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(path), m)) {
            out.flush();
        }
    }
}

package org.tinysep.drivers.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The list at start-up follows the distribution: a missing file is re-pointed to the new build's jar; a kept upload
 * (outside bundles/5-apps) stays unless the distribution brings a higher version of it (issue 13).
 */
class SeedTest {

    @TempDir
    Path home;

    private Path jar(String relative, String bsn, String version) throws IOException {
        Path file = home.resolve(relative);
        Files.createDirectories(file.getParent());
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        m.getMainAttributes().putValue("Bundle-SymbolicName", bsn);
        m.getMainAttributes().putValue("Bundle-Version", version);
        try (OutputStream out = Files.newOutputStream(file); JarOutputStream jar = new JarOutputStream(out, m)) {
            jar.flush();
        }
        return file;
    }

    private List<DriverEntry> repoint(String uploadVersion, String distributionVersion) throws IOException {
        jar("bundles/5-apps/x-" + distributionVersion + ".jar", "x", distributionVersion);
        jar("var/web/uploads/x.jar", "x", uploadVersion);
        Locations locations = new Locations(home);
        return Seed.repoint(List.of(new DriverEntry("var/web/uploads/x.jar", "x", true, "ACTIVE")),
                home.resolve("bundles/5-apps"), locations);
    }

    @Test
    void aNewerUploadStaysInTheList() throws IOException {
        assertEquals("var/web/uploads/x.jar", repoint("0.1.1", "0.1.0.202611251911").get(0).location());
    }

    @Test
    void anUploadOfTheSameVersionStaysInTheList() throws IOException {
        assertEquals("var/web/uploads/x.jar", repoint("0.1.0", "0.1.0").get(0).location());
    }

    @Test
    void aNewerDistributionWinsOverAnOlderUpload() throws IOException {
        DriverEntry e = repoint("0.1.1", "0.2.0").get(0);
        assertEquals("bundles/5-apps/x-0.2.0.jar", e.location());
        assertEquals(true, e.enabled());
    }

    @Test
    void aMissingFileIsRepointedToTheNewBuild() throws IOException {
        jar("bundles/5-apps/y-0.2.0.jar", "y", "0.2.0");
        List<DriverEntry> out = Seed.repoint(List.of(new DriverEntry("bundles/5-apps/y-0.1.0.jar", "y", false, "")),
                home.resolve("bundles/5-apps"), new Locations(home));
        assertEquals(new DriverEntry("bundles/5-apps/y-0.2.0.jar", "y", false, ""), out.get(0));
    }
}

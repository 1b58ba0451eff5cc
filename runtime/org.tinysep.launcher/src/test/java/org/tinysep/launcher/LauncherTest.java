package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.Map;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.Bundle;
import org.osgi.framework.startlevel.BundleStartLevel;

/** The launcher on a tiny hand-made distribution: ordering, start levels, failure report, shell handling. */
class LauncherTest {

    @TempDir
    Path home;
    private Launcher launcher;

    @BeforeEach
    void distribution() throws IOException {
        bundle("1-first/a.jar", Map.of("Bundle-SymbolicName", "test.a"));
        bundle("3-third/broken.jar", Map.of("Bundle-SymbolicName", "test.broken", "Import-Package", "does.not.exist"));
        bundle("3-third/fragment.jar", Map.of("Bundle-SymbolicName", "test.fragment", "Fragment-Host", "test.a"));
        bundle("3-third/shell.jar", Map.of("Bundle-SymbolicName", Launcher.SHELL_BSN + ";singleton:=true"));
        Files.createDirectories(home.resolve("bundles/not-a-group"));
    }

    @AfterEach
    void stop() {
        if (launcher != null) {
            launcher.stop(Duration.ofSeconds(10));
        }
    }

    /** Issue 10 item 6: the state folder holds alert texts and settings; the launcher makes it private. */
    @Test
    void theStateFolderIsMadePrivateToItsOwnerAtStart() throws Exception {
        Path var = Files.createDirectories(home.resolve("var"));
        Files.setPosixFilePermissions(var, java.nio.file.attribute.PosixFilePermissions.fromString("rwxr-xr-x"));
        launcher = new Launcher(new Options(true, home, false));
        launcher.start();
        assertEquals("rwx------", java.nio.file.attribute.PosixFilePermissions.toString(
                Files.getPosixFilePermissions(var)));
        assertEquals(java.util.Optional.empty(), PrivateFolder.tighten(var), "no warning once private");
        Files.setPosixFilePermissions(var, java.nio.file.attribute.PosixFilePermissions.fromString("rwxr-x---"));
        String warning = PrivateFolder.tighten(var).orElseThrow();
        assertTrue(warning.contains("was open to other users") && warning.contains("rwxr-x---"), warning);
        Path fresh = home.resolve("fresh/var");
        assertEquals(java.util.Optional.empty(), PrivateFolder.tighten(fresh), "a new folder: no warning");
        assertEquals("rwx------", java.nio.file.attribute.PosixFilePermissions.toString(
                Files.getPosixFilePermissions(fresh)));
    }

    @Test
    void daemonInstallsByGroupAndReportsTheBrokenBundle() throws Exception {
        launcher = new Launcher(new Options(true, home, false));
        StartReport report = launcher.start();

        assertEquals(3, report.startLevel());
        assertEquals(3, report.installed(), "shell left out in daemon mode");
        assertEquals(Map.of("1-first", 1, "3-third", 1), report.active());
        assertEquals(1, report.failures().size(), () -> String.join("\n", report.lines()));
        StartReport.Failure failure = report.failures().get(0);
        assertEquals("test.broken 0.0.0", failure.bundle());
        assertEquals("3-third", failure.group());
        assertTrue(failure.reason().startsWith("missing requirement osgi.wiring.package"), failure.reason());
        assertTrue(failure.reason().contains("does.not.exist"), failure.reason());

        assertEquals(1, find("test.a").adapt(BundleStartLevel.class).getStartLevel());
        assertEquals(3, find("test.broken").adapt(BundleStartLevel.class).getStartLevel());
        assertEquals(null, find(Launcher.SHELL_BSN));
        assertTrue(Files.isDirectory(home.resolve("var/felix-cache")));
        assertTrue(Files.isDirectory(home.resolve("deploy")));
    }

    @Test
    void appsAreLeftToTheDriversListWhenItIsPartOfTheDistribution() throws Exception {
        bundle("4-platform/drivers.jar", Map.of("Bundle-SymbolicName", Launcher.DRIVERS_BSN));
        bundle("5-apps/app.jar", Map.of("Bundle-SymbolicName", "test.app"));
        Path var = home.resolve("elsewhere/state");
        launcher = new Launcher(new Options(true, home, var, false));
        StartReport report = launcher.start();
        assertEquals(null, find("test.app"), "the launcher no longer installs 5-apps");
        assertEquals(0, report.active().get("5-apps"), "the group is still reported");
        assertEquals(5, report.startLevel());
        assertTrue(Files.isDirectory(var.resolve("felix-cache")), "framework cache in the state folder");
        assertEquals(var.toString(), launcher.framework().getBundleContext().getProperty("tinysep.var"));
    }

    @Test
    void withoutTheDriversListTheLauncherInstallsAppsItself() throws Exception {
        bundle("5-apps/app.jar", Map.of("Bundle-SymbolicName", "test.app"));
        launcher = new Launcher(new Options(true, home, false));
        StartReport report = launcher.start();
        assertEquals(Bundle.ACTIVE, find("test.app").getState());
        assertEquals(1, report.active().get("5-apps"));
    }

    @Test
    void interactiveStartsTheShellOnlyWhenAsked() throws Exception {
        launcher = new Launcher(new Options(false, home, false));
        launcher.start();
        Bundle shell = find(Launcher.SHELL_BSN);
        assertFalse(shell.getState() == Bundle.ACTIVE, "shell must wait for the banner");
        launcher.startShell();
        assertEquals(Bundle.ACTIVE, shell.getState());
    }

    @Test
    void stopIsCleanAndIdempotent() throws Exception {
        launcher = new Launcher(new Options(true, home, false));
        launcher.start();
        launcher.stop(Duration.ofSeconds(10));
        launcher.stop(Duration.ofSeconds(10));
        assertEquals(0, launcher.awaitStop());
        assertEquals(Bundle.RESOLVED, launcher.framework().getState());
    }

    private Bundle find(String bsn) {
        return Arrays.stream(launcher.framework().getBundleContext().getBundles())
                .filter(b -> bsn.equals(b.getSymbolicName())).findFirst().orElse(null);
    }

    private void bundle(String relative, Map<String, String> headers) throws IOException {
        Path jar = home.resolve("bundles").resolve(relative);
        Files.createDirectories(jar.getParent());
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        m.getMainAttributes().putValue("Bundle-ManifestVersion", "2");
        headers.forEach(m.getMainAttributes()::putValue);
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar), m)) {
            out.flush();
        }
    }
}

package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.Arrays;
import java.util.function.BooleanSupplier;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;

/**
 * Boots a copy of the assembled distribution ({@code target/tinysep}, system property {@code tinysep.dist}) in
 * this JVM as a daemon, drives it through the Gogo {@code CommandProcessor} and FileInstall, and stops it. The copy
 * configures the UDP bus radio on port 0 so the test never collides with a running TinySEP.
 */
class DistributionIT {

    private static final String UDP_PID = "org.tinysep.amica.busradio.udp";

    @TempDir
    static Path home;
    private static TestDistribution dist;
    private static Launcher launcher;
    private static StartReport report;

    @BeforeAll
    static void boot() throws Exception {
        dist = new TestDistribution(home, null);
        report = dist.start();
        launcher = dist.launcher();
        // at once, before any test: how soon after the banner the console answers HTTP (it starts after it)
        try {
            webAnswered = WebConsoleProbe.awaitAnswer(dist.httpPort(), Duration.ofSeconds(30));
        } catch (AssertionError none) {
            webAnswered = Long.MAX_VALUE; // theWebConsoleAnswersSoonAfterTheBanner fails; the other tests run
        }
    }

    private static long webAnswered;

    @AfterAll
    static void shutdown() {
        if (launcher != null) {
            launcher.stop(Duration.ofSeconds(30));
            assertEquals(Bundle.RESOLVED, launcher.framework().getState(), "framework stopped");
        }
    }

    @Test
    void everyBundleOfTheDistributionIsActive() {
        assertEquals(report.installed(), report.activeCount(), () -> String.join("\n", report.lines()));
        assertTrue(report.failures().isEmpty(), () -> String.join("\n", report.lines()));
        assertEquals(5, report.startLevel());
    }

    @Test
    void theBannerSaysPlainlyThatAlertsGoOnlyToTheLogWithoutAnSmtpHost() throws Exception {
        String line = launcher.alertsLine(Duration.ofSeconds(20));
        assertEquals("WARNING: alerts: no SMTP host configured: alerts are only written to the log", line);
    }

    @Test
    void slf4jInsideTheFrameworkIsBoundToSimpleLogger() throws Exception {
        Class<?> factory = bundle("org.tinysep.runtime").loadClass("org.slf4j.LoggerFactory");
        Object loggerFactory = factory.getMethod("getILoggerFactory").invoke(null);
        assertEquals("org.slf4j.simple.SimpleLoggerFactory", loggerFactory.getClass().getName(),
                "SLF4J inside the framework must not fall back to NOP (pitfall 1)");
        assertEquals(org.slf4j.LoggerFactory.class, factory, "the bundles log through the launcher's SLF4J");
    }

    @Test
    void nothingWeavesBytecodeAtStart() throws Exception {
        // issue 29: SPI Fly's weaving of Jetty, JAXB and SLF4J was a quarter of the start's CPU
        assertTrue(Arrays.stream(context().getBundles()).noneMatch(b -> String.valueOf(b.getSymbolicName())
                .startsWith("org.apache.aries.spifly")), "no Service Loader Mediator in the distribution");
        assertTrue(context().getServiceReferences(org.osgi.framework.hooks.weaving.WeavingHook.class.getName(), null)
                == null, "no weaving hook registered");
    }

    @Test
    void theWebConsoleAnswersSoonAfterTheBanner() throws Exception {
        // its group starts after the banner (issue 29): HTTP answers within a bound of it, on the configured port
        assertTrue(webAnswered != Long.MAX_VALUE, "the web console did not answer HTTP within 30 s of the banner");
        double seconds = (webAnswered - dist.bannerNanos()) / 1e9;
        System.out.printf("web console answered %.2f s after the banner%n", seconds);
        assertTrue(seconds <= WebConsoleProbe.BOUND.toSeconds(), "the console answers within "
                + WebConsoleProbe.BOUND.toSeconds() + " s of the banner (load permitting): " + seconds + " s");
    }

    @Test
    void daemonModeLeavesTheInteractiveShellOut() {
        assertTrue(Arrays.stream(context().getBundles()).noneMatch(b -> Launcher.SHELL_BSN.equals(b.getSymbolicName())));
    }

    @Test
    void driversCommandListsEveryDriver() throws Exception {
        String out = shell("tinysep:drivers");
        System.out.println("tinysep:drivers →\n" + out);
        ServiceReference<?>[] drivers = context().getAllServiceReferences("org.tinysep.api.device.Driver", null);
        for (ServiceReference<?> driver : drivers == null ? new ServiceReference<?>[0] : drivers) {
            String name = String.valueOf(driver.getProperty("tinysep.driver.name"));
            assertTrue(out.contains(name), () -> "driver " + name + " missing from:\n" + out);
        }
    }

    @Test
    void busRadioTakesItsConfigurationFromEtc() {
        if (bundle(UDP_PID) == null) {
            System.out.println("SKIPPED: " + UDP_PID + " is not part of this distribution");
            return;
        }
        await(Duration.ofSeconds(15), () -> udpPort() > 0, "the UDP bus radio publishing tinysep.udp.port > 0");
    }

    @Test
    void jarDroppedIntoDeployIsInstalledAndRemoved() throws Exception {
        Path jar = home.resolve("deploy/hotdeploy-test.jar");
        writeEmptyBundle(jar, "org.tinysep.launcher.hotdeploy.test");
        await(Duration.ofSeconds(15), () -> isActive(bundle("org.tinysep.launcher.hotdeploy.test")), "hot-deployed bundle ACTIVE");
        Files.delete(jar);
        await(Duration.ofSeconds(15), () -> bundle("org.tinysep.launcher.hotdeploy.test") == null, "hot-deployed bundle uninstalled");
    }

    // ---- helpers

    private static BundleContext context() {
        return launcher.framework().getBundleContext();
    }

    private static Bundle bundle(String bsn) {
        return dist.bundle(bsn);
    }

    private static boolean isActive(Bundle b) {
        return b != null && b.getState() == Bundle.ACTIVE;
    }

    private static int udpPort() {
        try {
            ServiceReference<?>[] refs = context().getAllServiceReferences("org.tinysep.api.device.Driver",
                    "(&(tinysep.driver.name=BusRadioAmicaUdp)(tinysep.udp.port=*))");
            return refs == null ? -1 : Integer.parseInt(String.valueOf(refs[0].getProperty("tinysep.udp.port")));
        } catch (Exception e) {
            return -1;
        }
    }

    private static String shell(String commandLine) throws Exception {
        return dist.shell(commandLine);
    }

    private static void await(Duration timeout, BooleanSupplier condition, String what) {
        TestDistribution.await(timeout, condition, what);
    }

    private static void writeEmptyBundle(Path jar, String bsn) throws IOException {
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        m.getMainAttributes().putValue("Bundle-ManifestVersion", "2");
        m.getMainAttributes().putValue("Bundle-SymbolicName", bsn);
        m.getMainAttributes().putValue("Bundle-Version", "1.0.0");
        Path tmp = jar.resolveSibling(jar.getFileName() + ".tmp");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(tmp), m)) {
            out.flush();
        }
        Files.move(tmp, jar, StandardCopyOption.ATOMIC_MOVE);
    }
}

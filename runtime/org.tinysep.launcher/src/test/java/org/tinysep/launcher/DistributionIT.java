package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.Arrays;
import java.util.function.BooleanSupplier;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.stream.Stream;
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
    private static Launcher launcher;
    private static StartReport report;

    @BeforeAll
    static void boot() throws Exception {
        LoggingDefaults.apply();
        copyDistribution(Path.of(System.getProperty("tinysep.dist", "target/tinysep")), home);
        Files.writeString(home.resolve("etc/" + UDP_PID + ".cfg"), "port=0\nbindAddress=127.0.0.1\n");
        Files.writeString(home.resolve("etc/org.tinysep.sunspot.busradio.cfg"), "udpPort=0\nudpBindAddress=127.0.0.1\n");
        launcher = new Launcher(new Options(true, home, false));
        report = launcher.start();
        report.lines().forEach(System.out::println);
    }

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
    void slf4jInsideTheFrameworkIsBoundToSimpleLogger() throws Exception {
        Class<?> factory = bundle("slf4j.api").loadClass("org.slf4j.LoggerFactory");
        Object loggerFactory = factory.getMethod("getILoggerFactory").invoke(null);
        assertEquals("org.slf4j.simple.SimpleLoggerFactory", loggerFactory.getClass().getName(),
                "SLF4J inside the framework must not fall back to NOP (pitfall 1)");
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
        return Arrays.stream(context().getBundles()).filter(b -> bsn.equals(b.getSymbolicName())).findFirst().orElse(null);
    }

    private static boolean isActive(Bundle b) {
        return b != null && b.getState() == Bundle.ACTIVE;
    }

    private static boolean hasService(String type) {
        try {
            return context().getAllServiceReferences(type, null) != null;
        } catch (Exception e) {
            return false;
        }
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

    /** Executes a Gogo command through the CommandProcessor service (reflectively: its classes live in a bundle). */
    private static String shell(String commandLine) throws Exception {
        await(Duration.ofSeconds(10), () -> hasService("org.apache.felix.service.command.CommandProcessor"),
                "Gogo CommandProcessor service");
        // getAll…: this JVM's class path holds Gogo too, so the assignability check of getServiceReference would hide it
        ServiceReference<?> ref = context().getAllServiceReferences("org.apache.felix.service.command.CommandProcessor", null)[0];
        Object processor = context().getService(ref);
        Class<?> processorType = ref.getBundle().loadClass("org.apache.felix.service.command.CommandProcessor");
        Class<?> sessionType = ref.getBundle().loadClass("org.apache.felix.service.command.CommandSession");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        Object session = processorType.getMethod("createSession", InputStream.class, OutputStream.class, OutputStream.class)
                .invoke(processor, new ByteArrayInputStream(new byte[0]), out, out);
        try {
            Object result = sessionType.getMethod("execute", CharSequence.class).invoke(session, commandLine);
            if (result != null) {
                Method format = sessionType.getMethod("format", Object.class, int.class);
                out.write(String.valueOf(format.invoke(session, result, 0)).getBytes(StandardCharsets.UTF_8));
            }
        } catch (InvocationTargetException e) {
            fail("'" + commandLine + "' failed: " + e.getCause() + "\n" + out.toString(StandardCharsets.UTF_8));
        } finally {
            sessionType.getMethod("close").invoke(session);
            context().ungetService(ref);
        }
        return out.toString(StandardCharsets.UTF_8);
    }

    private static void await(Duration timeout, BooleanSupplier condition, String what) {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                fail("Timed out after " + timeout.toSeconds() + " s waiting for " + what);
            }
            try {
                Thread.sleep(50);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                fail("interrupted waiting for " + what);
            }
        }
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

    private static void copyDistribution(Path from, Path to) throws IOException {
        assertTrue(Files.isDirectory(from.resolve("bundles")), "no distribution at " + from.toAbsolutePath());
        try (Stream<Path> files = Files.walk(from)) {
            for (Path f : files.filter(p -> !from.relativize(p).startsWith("var")).toList()) {
                Path target = to.resolve(from.relativize(f).toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(f, target, StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
    }
}

package org.tinysep.launcher;

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
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.stream.Stream;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.tinysep.tools.process.DistributionCopy;
import org.tinysep.tools.process.Ports;

/** A copy of the assembled distribution booted in this JVM, with helpers to drive it (shell, polling). */
final class TestDistribution {

    static final String UDP_PID = "org.tinysep.amica.busradio.udp";

    private final Path home;
    private final Path var;
    private Launcher launcher;

    /** Copies {@code target/tinysep} (system property {@code tinysep.dist}) to {@code home}; UDP radios on port 0. */
    TestDistribution(Path home, Path var) throws IOException {
        this.home = home;
        this.var = var;
        copy(Path.of(System.getProperty("tinysep.dist", "target/tinysep")), home);
        Files.writeString(home.resolve("etc/" + UDP_PID + ".cfg"), "port=0\nbindAddress=127.0.0.1\n");
        Files.writeString(home.resolve("etc/org.tinysep.sunspot.busradio.cfg"), "udpPort=0\nudpBindAddress=127.0.0.1\n");
        httpPort = Ports.freeTcp(); // the web console on a port nobody holds (8080 may be another TinySEP's)
        Files.writeString(home.resolve("etc/org.apache.felix.http.cfg"),
                "org.apache.felix.http.host=127.0.0.1\norg.osgi.service.http.port=" + httpPort + "\n");
    }

    private final int httpPort;
    private boolean headless;
    private long bannerNanos;

    /** The next {@link #start()} is of the headless gateway profile ({@code --headless}). @return this */
    TestDistribution headless() {
        headless = true;
        return this;
    }

    /** @return the web console's port, as this copy's {@code etc/org.apache.felix.http.cfg} sets it */
    int httpPort() {
        return httpPort;
    }

    /** @return {@link System#nanoTime()} when the last {@link #start()} had its banner */
    long bannerNanos() {
        return bannerNanos;
    }

    /** Runs the time controller in real time (synchroniser on port 0), as process tests want it. @return this */
    TestDistribution realTime() throws IOException {
        Files.writeString(home.resolve("etc/org.tinysep.timecontroller.cfg"),
                "mode=REAL\nsyncPort=0\nsyncBindAddress=127.0.0.1\n");
        return this;
    }

    /**
     * For tests that play AmICA nodes over UDP ({@link AmicaSender}) to the distribution run as a process: the UDP bus
     * radio on a free port of 127.0.0.1 (port 0 would hide it from the test), the time controller in real time.
     *
     * @return the bus radio's port
     */
    int realTimeAmicaRadio() throws IOException {
        int port = Ports.freeUdp();
        Files.writeString(home.resolve("etc/" + UDP_PID + ".cfg"), "port=" + port + "\nbindAddress=127.0.0.1\n");
        realTime();
        return port;
    }

    StartReport start() throws Exception {
        LoggingDefaults.apply();
        Path state = var == null ? home.resolve("var") : var;
        launcher = new Launcher(new Options(true, home, state, false, false, headless));
        StartReport report = launcher.start();
        bannerNanos = System.nanoTime();
        report.lines().forEach(System.out::println);
        // as Main does: the web console's group starts after the banner
        Main.webConsole(launcher, launcher.options(), bannerNanos).forEach(System.out::println);
        return report;
    }

    void stop() {
        if (launcher != null) {
            launcher.stop(Duration.ofSeconds(30));
        }
    }

    /** Stops and starts again; fails with the start report when anything failed to start. @return the report */
    StartReport restart() throws Exception {
        stop();
        StartReport report = start();
        assertTrue(report.failures().isEmpty(), () -> String.join("\n", report.lines()));
        return report;
    }

    /** @return the jars of {@code bundles/5-apps} in this copy (the applications the drivers list is seeded from) */
    List<Path> apps() throws IOException {
        try (Stream<Path> jars = Files.list(home.resolve("bundles/5-apps"))) {
            return jars.toList();
        }
    }

    Launcher launcher() {
        return launcher;
    }

    Path home() {
        return home;
    }

    BundleContext context() {
        return launcher.framework().getBundleContext();
    }

    Bundle bundle(String bsn) {
        return Arrays.stream(context().getBundles()).filter(b -> bsn.equals(b.getSymbolicName())).findFirst().orElse(null);
    }

    boolean hasService(String type, String filter) {
        try {
            return context().getAllServiceReferences(type, filter) != null;
        } catch (Exception e) {
            return false;
        }
    }

    boolean hasDriver(String name) {
        return hasService("org.tinysep.api.device.Driver", "(tinysep.driver.name=" + name + ")");
    }

    /** Executes a Gogo command through the CommandProcessor service (reflectively: its classes live in a bundle). */
    String shell(String commandLine) throws Exception {
        await(Duration.ofSeconds(10), () -> hasService("org.apache.felix.service.command.CommandProcessor", null),
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
            throw new ShellFailure("'" + commandLine + "' failed: " + e.getCause().getMessage() + "\n"
                    + out.toString(StandardCharsets.UTF_8));
        } finally {
            sessionType.getMethod("close").invoke(session);
            context().ungetService(ref);
        }
        String text = out.toString(StandardCharsets.UTF_8);
        System.out.println("g! " + commandLine + "\n" + text);
        return text;
    }

    /** A shell command that failed; the message holds the command's error and output. */
    static final class ShellFailure extends Exception {
        private static final long serialVersionUID = 1L;

        ShellFailure(String message) {
            super(message);
        }
    }

    static void await(Duration timeout, BooleanSupplier condition, String what) {
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

    private static void copy(Path from, Path to) throws IOException {
        assertTrue(Files.isDirectory(from.resolve("bundles")), "no distribution at " + from.toAbsolutePath());
        DistributionCopy.copy(from, to);
    }
}

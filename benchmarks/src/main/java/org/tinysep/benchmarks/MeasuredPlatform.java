package org.tinysep.benchmarks;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.tools.process.Banner;
import org.tinysep.tools.process.DistributionCopy;
import org.tinysep.tools.process.PlatformProcess;
import org.tinysep.tools.process.Ports;

/**
 * The real distribution run as a user runs it: {@code java <options> -jar tinysep.jar --var <state>} in a copy of
 * {@code runtime/org.tinysep.launcher/target/tinysep}, with its interactive shell on stdin ({@link PlatformProcess},
 * the helper the launcher's process tests, the integration tests and the evaluation use too), its log in {@code
 * <home>/platform.log}. Its radios listen on free loopback ports.
 */
final class MeasuredPlatform implements AutoCloseable {

    /** Not handed down from the shell that runs the benchmarks, to the floors ({@link Child}) nor the platform. */
    static final List<String> UNSET = List.of("MALLOC_ARENA_MAX", "JAVA_TOOL_OPTIONS");

    final Path home;
    final int amicaPort;
    private final PlatformProcess shell;
    private final WebLine web;

    private MeasuredPlatform(Path home, int amicaPort, PlatformProcess shell, WebLine web) {
        this.home = home;
        this.amicaPort = amicaPort;
        this.shell = shell;
        this.web = web;
    }

    /** Copies the distribution to {@code home} and sets its ports: AmICA, Time Controller as given, the rest free. */
    static Path install(Path dist, Path home, int amicaPort, int syncPort) throws IOException {
        DistributionCopy.copy(DistributionCopy.require(dist), home);
        DistributionCopy.cfg(home, "org.tinysep.amica.busradio.udp",
                "port=" + amicaPort + "\nbindAddress=127.0.0.1\nmaxNodes=20000\n"); // scale: above its default 1,000
        DistributionCopy.cfg(home, "org.tinysep.sunspot.busradio", "udpPort=0\nudpBindAddress=127.0.0.1\n");
        DistributionCopy.cfg(home, "org.tinysep.timecontroller", "syncPort=" + syncPort + "\n");
        DistributionCopy.cfg(home, "org.apache.felix.http",
                "org.apache.felix.http.host=127.0.0.1\norg.osgi.service.http.port=" + Ports.freeTcp() + "\n");
        return home;
    }

    /** Starts {@code java <jvmOptions> -jar tinysep.jar --var <var>} in {@code home}; waits for the shell. */
    static MeasuredPlatform start(Path home, Path var, int amicaPort, List<String> jvmOptions) throws IOException {
        List<String> options = new ArrayList<>(jvmOptions);
        String extra = System.getenv("BENCH_PLATFORM_JVM"); // e.g. a JFR recording while profiling (README)
        if (extra != null && !extra.isBlank()) {
            options.addAll(List.of(extra.strip().split("\\s+")));
        }
        WebLine web = new WebLine();
        PlatformProcess p = PlatformProcess.in(home).java(Machine.java()).jvm(options)
                .unsetEnv(UNSET.toArray(String[]::new)).args("--var", var.toString()).eachLine(web)
                .stopTimeout(Duration.ofMinutes(5)).start(Duration.ofSeconds(180));
        return new MeasuredPlatform(home, amicaPort, p, web);
    }

    /** Notes when the line "Web console: …" came (bound after the banner, or its port held until its first use). */
    private static final class WebLine implements java.util.function.Consumer<String> {
        private volatile long nanos;

        @Override
        public void accept(String line) {
            if (nanos == 0 && line.startsWith("Web console: ")) {
                nanos = System.nanoTime();
            }
        }
    }

    /** @return the process's CPU time (user + system) when the banner came, in ms; NaN if unknown */
    double cpuMsToBanner() {
        Banner b = shell.banner();
        return b == null ? Double.NaN : b.cpuMs();
    }

    /** @return ms from the banner to the line "Web console: <address>" (bound); NaN without one */
    double msBannerToWeb() {
        return web.nanos == 0 ? Double.NaN : (web.nanos - shell.startNanos()) / 1e6 - shell.msToBanner();
    }

    /**
     * Asks the web console for its login page, as a browser's first visit does (when the console starts on its first
     * use, this request starts it: issue 29).
     *
     * @return ms until the answer came; NaN when none came within 30 s or the distribution has no console address
     */
    double msToFirstWebAnswer() throws IOException, InterruptedException {
        java.util.Properties http = new java.util.Properties();
        try (java.io.Reader r = java.nio.file.Files.newBufferedReader(home.resolve("etc/org.apache.felix.http.cfg"))) {
            http.load(r);
        }
        String port = http.getProperty("org.osgi.service.http.port");
        if (port == null) {
            return Double.NaN;
        }
        java.net.http.HttpRequest request = java.net.http.HttpRequest.newBuilder(
                java.net.URI.create("http://127.0.0.1:" + port.strip() + "/login.html")).timeout(Duration.ofSeconds(30)).build();
        long t0 = System.nanoTime();
        try {
            java.net.http.HttpClient.newHttpClient().send(request, java.net.http.HttpResponse.BodyHandlers.discarding());
        } catch (IOException e) {
            return Double.NaN;
        }
        return (System.nanoTime() - t0) / 1e6;
    }

    /** @return ms from closing the shell's input to the process's end (0 before {@link #close}) */
    double msToStop() {
        return shell.msToStop();
    }

    long pid() {
        return shell.pid();
    }

    /** @return wall time from {@code java -jar} to the banner "…: n/n bundles active", in ms */
    double msToBanner() {
        return shell.msToBanner();
    }

    double msSinceStart() {
        return shell.msSinceStart();
    }

    String banner() {
        Banner b = shell.banner();
        return b == null ? "" : b.line();
    }

    /** Runs one shell command; @return its output lines (prompts removed) */
    List<String> command(String commandLine, Duration timeout) {
        try {
            return shell.command(commandLine, timeout);
        } catch (IllegalStateException e) {
            throw new IllegalStateException(e.getMessage() + " (log: " + shell.log() + ")", e);
        }
    }

    long rssKb() {
        return Proc.rssKb(pid());
    }

    long liveHeapKb() {
        return Proc.liveHeapKb(pid());
    }

    /**
     * Ends the shell's input: the shell stops the framework cleanly, after the platform saved what its backup writer
     * still holds (bounded by the launcher).
     *
     * @throws IllegalStateException when it did not stop within 5 min (it is then killed; the message has its last
     *                               lines)
     */
    @Override
    public void close() throws InterruptedException {
        if (shell.alive()) {
            shell.stop(Duration.ofMinutes(5));
        }
    }
}

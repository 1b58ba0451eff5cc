package org.tinysep.benchmarks;

import java.io.IOException;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.testsupport.process.DistributionCopy;
import org.tinysep.testsupport.process.PlatformProcess;

/**
 * The real distribution run as a user runs it: {@code java <options> -jar tinysep.jar --var <state>} in a copy of
 * {@code runtime/org.tinysep.launcher/target/tinysep}, with its interactive shell on stdin (commands end with an
 * {@code echo} marker: {@link PlatformProcess}, the same conversation as the launcher's process tests), its log in
 * {@code <home>/platform.log}. Its radios listen on free loopback ports.
 */
final class Platform implements AutoCloseable {

    final Path home;
    final int amicaPort;
    private final PlatformProcess shell;
    private final long processId;
    private final long startNanos;
    private volatile long bannerNanos;
    private volatile String banner = "";
    private long stopNanos;

    private Platform(Path home, int amicaPort, Process process, long startNanos) {
        this.home = home;
        this.amicaPort = amicaPort;
        this.startNanos = startNanos;
        this.processId = process.pid();
        this.shell = PlatformProcess.attach(process, this::saw);
    }

    /** Copies the distribution to {@code home} and sets its ports: AmICA, Time Controller as given, the rest free. */
    static Path install(Path dist, Path home, int amicaPort, int syncPort) throws IOException {
        if (!Files.isRegularFile(dist.resolve("tinysep.jar"))) {
            throw new IOException("no distribution at " + dist.toAbsolutePath() + " (mvn -B -o package first)");
        }
        DistributionCopy.copy(dist, home);
        Files.writeString(home.resolve("etc/org.tinysep.amica.busradio.udp.cfg"),
                "port=" + amicaPort + "\nbindAddress=127.0.0.1\nmaxNodes=20000\n"); // scale: above its default 1,000
        Files.writeString(home.resolve("etc/org.tinysep.sunspot.busradio.cfg"), "udpPort=0\nudpBindAddress=127.0.0.1\n");
        Files.writeString(home.resolve("etc/org.tinysep.timecontroller.cfg"), "syncPort=" + syncPort + "\n");
        Files.writeString(home.resolve("etc/org.apache.felix.http.cfg"),
                "org.apache.felix.http.host=127.0.0.1\norg.osgi.service.http.port=" + freeTcpPort() + "\n");
        return home;
    }

    /** Starts {@code java <jvmOptions> -jar tinysep.jar --var <var>} in {@code home}; waits for the shell. */
    static Platform start(Path home, Path var, int amicaPort, List<String> jvmOptions) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Machine.java());
        cmd.addAll(jvmArgs(jvmOptions));
        String extra = System.getenv("BENCH_PLATFORM_JVM"); // e.g. a JFR recording while profiling (README)
        if (extra != null && !extra.isBlank()) {
            cmd.addAll(List.of(extra.strip().split("\\s+")));
        }
        cmd.addAll(List.of("-jar", "tinysep.jar", "--var", var.toString()));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(home.toFile())
                .redirectError(ProcessBuilder.Redirect.appendTo(home.resolve("platform.log").toFile()));
        environment(jvmOptions, pb);
        long t0 = System.nanoTime();
        Process p = Children.track(pb.start());
        Platform platform = new Platform(home, amicaPort, p, t0);
        platform.command("echo ready", Duration.ofSeconds(180));
        return platform;
    }

    private void saw(String line) {
        if (bannerNanos == 0 && line.contains("bundles active")) {
            bannerNanos = System.nanoTime();
            banner = line.strip();
            bannerCpuTicks = Proc.cpuTicks(processId);
        } else if (webNanos == 0 && line.startsWith("Web console: ")) {
            webNanos = System.nanoTime(); // issue 29: the console starts after the banner
        }
    }

    private volatile long bannerCpuTicks = -1;
    private volatile long webNanos;

    /** @return the process's CPU time (user + system) when the banner came, in ms; NaN if unknown */
    double cpuMsToBanner() {
        return bannerCpuTicks < 0 ? Double.NaN : bannerCpuTicks * 1000.0 / Proc.HZ;
    }

    /** @return ms from the banner to the line "Web console: <address>" (bound); NaN without one */
    double msBannerToWeb() {
        return webNanos == 0 || bannerNanos == 0 ? Double.NaN : (webNanos - bannerNanos) / 1e6;
    }

    /** @return ms from closing the shell's input to the process's end (0 before {@link #close}) */
    double msToStop() {
        return stopNanos / 1e6;
    }

    long pid() {
        return shell.pid();
    }

    /** @return wall time from {@code java -jar} to the banner "…: n/n bundles active", in ms */
    double msToBanner() {
        return bannerNanos == 0 ? Double.NaN : (bannerNanos - startNanos) / 1e6;
    }

    double msSinceStart() {
        return (System.nanoTime() - startNanos) / 1e6;
    }

    String banner() {
        return banner;
    }

    /** Runs one shell command; @return its output lines (prompts removed) */
    List<String> command(String commandLine, Duration timeout) {
        try {
            return shell.command(commandLine, timeout);
        } catch (IllegalStateException e) {
            throw new IllegalStateException(e.getMessage() + " (log: " + home.resolve("platform.log") + ")", e);
        }
    }

    long rssKb() {
        return Proc.rssKb(pid());
    }

    long liveHeapKb() {
        return Proc.liveHeapKb(pid());
    }

    @Override
    public void close() throws InterruptedException {
        if (shell.alive()) {
            long stopAsked = System.nanoTime();
            // end of input: the shell stops the framework cleanly, after the platform saved what its backup writer
            // still holds (bounded by the launcher)
            try {
                shell.stop(Duration.ofMinutes(5));
            } catch (IllegalStateException late) {
                throw new IllegalStateException("the platform did not stop within 5 min of its shell's end; killed"
                        + " (log: " + home.resolve("platform.log") + ")", late);
            }
            stopNanos = System.nanoTime() - stopAsked;
        }
    }

    /** @return the JVM arguments of an options list (entries starting with '-') */
    static List<String> jvmArgs(List<String> options) {
        return options.stream().filter(o -> o.startsWith("-")).toList();
    }

    /** Puts the environment entries of an options list ({@code NAME=value}, as etc/jvm.options has them) in pb's. */
    static void environment(List<String> options, ProcessBuilder pb) {
        pb.environment().remove("MALLOC_ARENA_MAX");
        pb.environment().remove("JAVA_TOOL_OPTIONS");
        for (String o : options) {
            if (!o.startsWith("-") && o.contains("=")) {
                pb.environment().put(o.substring(0, o.indexOf('=')), o.substring(o.indexOf('=') + 1));
            }
        }
    }

    static int freeUdpPort() throws IOException {
        try (DatagramSocket s = new DatagramSocket(0, InetAddress.getByName("127.0.0.1"))) {
            return s.getLocalPort();
        }
    }

    static int freeTcpPort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return s.getLocalPort();
        }
    }
}

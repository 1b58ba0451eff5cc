package org.tinysep.launcher;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code java -jar tinysep.jar [--daemon] [--home DIR]}: starts TinySEP, prints the banner, then offers the
 * Gogo shell (interactive) or waits for SIGTERM (daemon). A shutdown hook stops the framework cleanly.
 */
public final class Main {

    /**
     * How long the shutdown hook waits for the framework to stop (a SIGTERM, e.g. from systemd). Above the backup
     * store's limit for never-saved backups (stopSaveSeconds, 25 s, counted from its own stop, after the drivers'):
     * a burst of new devices just before the stop is saved, not cut off (a 10,000-device stop takes 38-60 s
     * at load; a normal one stays well below). The systemd unit's TimeoutStopSec is above this.
     */
    static final Duration STOP_TIMEOUT = Duration.ofSeconds(60);
    /** How long the banner waits for the Mail Manager (started by the drivers list) to say where alerts go. */
    private static final Duration ALERTS_WAIT = Duration.ofSeconds(5);

    private Main() {
    }

    static final String JSERIALCOMM_RANDOM_NAME = "jSerialComm.library.randomizeNativeName";

    public static void main(String[] args) {
        LoggingDefaults.apply(); // before the first logger
        // jSerialComm loads its JNI library per class loader and the JVM refuses one library file in a second
        // loader: without a random file name, updating the jSerialComm bundle at runtime breaks every serial port
        if (System.getProperty(JSERIALCOMM_RANDOM_NAME) == null) {
            System.setProperty(JSERIALCOMM_RANDOM_NAME, "true");
        }
        Options options;
        Optional<String> passwordRole;
        try {
            passwordRole = WebPassword.role(Arrays.asList(args));
            options = Options.parse(WebPassword.rest(Arrays.asList(args)), System.getenv(),
                    Options.defaultHome(launcherJar()));
        } catch (IllegalArgumentException e) { // one line naming it, as the tools' command lines (tools.cli) say it
            System.err.println("error: " + e.getMessage());
            System.err.println(Options.USAGE);
            System.exit(2);
            return;
        }
        if (options.help()) {
            System.out.println(Options.USAGE);
            return;
        }
        if (passwordRole.isPresent()) {
            System.exit(WebPassword.run(passwordRole.get(), options.var()));
            return;
        }
        if (options.supervise()) {
            System.exit(supervise(options, args));
            return;
        }
        System.exit(run(options));
    }

    /** {@code --supervise}: runs the platform as a child process and restarts it when it fails or hangs. */
    static int supervise(Options options, String[] args) {
        Path jar = launcherJar();
        if (jar == null || !Files.isRegularFile(jar)) {
            System.err.println("--supervise needs the launcher started as java -jar tinysep.jar");
            return 2;
        }
        List<String> rest = Arrays.stream(args).filter(a -> !"--supervise".equals(a)).toList();
        try {
            return new Supervisor(options.var(), rest).run(jar);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 1;
        }
    }

    /** Runs TinySEP until the framework stops; returns the exit code. */
    static int run(Options options) {
        Logger log = LoggerFactory.getLogger(Main.class);
        Launcher launcher = new Launcher(options);
        HeartbeatFile heartbeat = new HeartbeatFile(options.var());
        Optional<SdNotify> systemd = SdNotify.fromEnvironment(System.getenv());
        Heartbeat[] beating = new Heartbeat[1];
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            systemd.ifPresent(SdNotify::stopping);
            if (beating[0] != null) {
                beating[0].close();
            }
            launcher.stop(STOP_TIMEOUT);
            stopped(heartbeat, log);
        }, "tinysep-shutdown"));
        try {
            HeartbeatFile.noteRestart(options.var(), Instant.now(), ZoneId.systemDefault())
                    .ifPresent(s -> log.warn("{} (the event log and the caregivers are told)", s));
            heartbeat.write("STARTING", Instant.now());
            StartReport report = launcher.start();
            long banner = System.nanoTime();
            report.lines().forEach(System.out::println);
            System.out.println(launcher.alertsLine(ALERTS_WAIT));
            System.out.flush();
            beating[0] = new Heartbeat(new LivenessProbe(launcher.framework()), heartbeat, systemd,
                    Heartbeat.interval(SdNotify.watchdogInterval(System.getenv())));
            beating[0].start();
            systemd.ifPresent(s -> s.ready(report.lines().get(0)));
            // the web console on its first use: its HTTP service (Jetty) is neither on the start path nor idle
            webConsole(launcher, options, banner).forEach(System.out::println);
            System.out.flush();
            launcher.startShell();
            int code = launcher.awaitStop();
            beating[0].close();
            if (code == 0) {
                stopped(heartbeat, log);
            }
            return code;
        } catch (Exception e) {
            log.error("TinySEP could not start: {}", Failures.describe(e), e);
            launcher.stop(STOP_TIMEOUT);
            return 1;
        }
    }

    /**
     * Holds the web console's port until its first use ({@link WebConsole}: its bundles, {@code bundles/4-web}, start
     * then) when it serves plain HTTP on this machine only ({@link HttpCfg#onFirstUse}); otherwise, or when the port
     * cannot be held, starts them now and waits until the HTTP service has bound.
     *
     * @param banner {@link System#nanoTime()} when the banner was printed
     * @return the lines for below the banner: the console's address, or a warning; on a headless gateway the one
     *         line that says there is no console
     */
    static List<String> webConsole(Launcher launcher, Options options, long banner) throws InterruptedException {
        if (options.headless()) {
            return List.of("Headless gateway (--headless): no web console, no HTTP port; the shell and the event log"
                    + " say what the console would");
        }
        if (!launcher.hasWeb()) {
            return List.of("No web console in this distribution (no bundles/*-web group)");
        }
        InetSocketAddress at = WebConsole.address(launcher.framework().getBundleContext());
        if (HttpCfg.onFirstUse(options.home().resolve("etc").resolve(HttpCfg.FILE))) { // plain HTTP, this machine
            try {
                WebConsole.onFirstUse(launcher, at);
                return List.of(WebConsoleLine.onFirstUse(at));
            } catch (IOException e) { // held by another program: Jetty will say so, and the line below
                LoggerFactory.getLogger(Main.class).warn("Cannot hold the web console's address {}: {}", at, e.toString());
            }
        }
        List<String> lines = new java.util.ArrayList<>();
        launcher.startWeb().forEach(f -> lines.add("  FAILED " + f.bundle() + " (" + f.group() + "): " + f.reason()));
        lines.add(WebConsoleLine.line(launcher.framework().getBundleContext(), WebConsoleLine.WAIT, banner));
        return lines;
    }

    /** A clean stop: the next start is not a restart after a failure. */
    private static void stopped(HeartbeatFile heartbeat, Logger log) {
        try {
            heartbeat.write("STOPPED", Instant.now());
        } catch (IOException e) {
            log.warn("Cannot write the heartbeat file: {}", e.toString());
        }
    }

    private static Path launcherJar() {
        try {
            return Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException | RuntimeException e) {
            return null;
        }
    }
}

package org.tinysep.launcher;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code java -jar tinysep.jar [--daemon] [--home DIR]}: starts TinySEP, prints the banner, then offers the
 * Gogo shell (interactive) or waits for SIGTERM (daemon). A shutdown hook stops the framework cleanly.
 */
public final class Main {

    private static final Duration STOP_TIMEOUT = Duration.ofSeconds(30);
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
        try {
            options = Options.parse(Arrays.asList(args), System.getenv(), Options.defaultHome(launcherJar()));
        } catch (IllegalArgumentException e) {
            System.err.println(e.getMessage());
            System.err.println(Options.USAGE);
            System.exit(2);
            return;
        }
        if (options.help()) {
            System.out.println(Options.USAGE);
            return;
        }
        System.exit(run(options));
    }

    /** Runs TinySEP until the framework stops; returns the exit code. */
    static int run(Options options) {
        Logger log = LoggerFactory.getLogger(Main.class);
        Launcher launcher = new Launcher(options);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> launcher.stop(STOP_TIMEOUT), "tinysep-shutdown"));
        try {
            StartReport report = launcher.start();
            report.lines().forEach(System.out::println);
            System.out.println(launcher.alertsLine(ALERTS_WAIT));
            System.out.flush();
            launcher.startShell();
            return launcher.awaitStop();
        } catch (Exception e) {
            log.error("TinySEP could not start: {}", Failures.describe(e), e);
            launcher.stop(STOP_TIMEOUT);
            return 1;
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

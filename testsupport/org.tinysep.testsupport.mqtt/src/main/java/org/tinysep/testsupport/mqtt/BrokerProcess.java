package org.tinysep.testsupport.mqtt;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/**
 * The broker's process: Debian's {@code mosquitto} binary started with a configuration, waited for until it accepts
 * connections on its port, stopped in order (SIGTERM, then SIGKILL) or killed. Only its own process.
 */
final class BrokerProcess {

    private static final Duration START_TIMEOUT = Duration.ofSeconds(30);

    private final Path config;
    private final Path log;
    private final int port;
    private final Supplier<String> logText;
    private Process process;

    BrokerProcess(Path config, Path log, int port, Supplier<String> logText) {
        this.config = config;
        this.log = log;
        this.port = port;
        this.logText = logText;
    }

    /** @return the path of the broker binary: {@code /usr/sbin/mosquitto} or the one on the PATH */
    static String binary() {
        for (String candidate : List.of("/usr/sbin/mosquitto", "/usr/local/sbin/mosquitto", "/usr/bin/mosquitto")) {
            if (Files.isExecutable(Path.of(candidate))) {
                return candidate;
            }
        }
        return "mosquitto";
    }

    static boolean onPath(String name) {
        String path = System.getenv().getOrDefault("PATH", "");
        for (String d : path.split(java.io.File.pathSeparator)) {
            if (!d.isEmpty() && Files.isExecutable(Path.of(d, name))) {
                return true;
            }
        }
        return false;
    }

    /** Starts the process unless it runs and waits until it accepts connections. */
    synchronized void start() {
        if (isRunning()) {
            return;
        }
        ProcessBuilder pb = new ProcessBuilder(binary(), "-c", config.toString())
                .redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile()));
        try {
            process = pb.start();
        } catch (IOException e) {
            throw new IllegalStateException("cannot run " + binary()
                    + " - is mosquitto installed (scripts/install-deps.sh)? " + e.getMessage(), e);
        }
        Instant deadline = Instant.now().plus(START_TIMEOUT);
        while (Instant.now().isBefore(deadline)) {
            if (!process.isAlive()) {
                throw new IllegalStateException("mosquitto exited with " + process.exitValue()
                        + " on port " + port + "; its log:\n" + logText.get());
            }
            if (accepts()) {
                return;
            }
            sleep(50);
        }
        stop();
        throw new IllegalStateException("mosquitto did not accept connections on 127.0.0.1:" + port + " within "
                + START_TIMEOUT.toSeconds() + " s; its log:\n" + logText.get());
    }

    private boolean accepts() {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 500);
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /** SIGTERM, then SIGKILL after 10 s; waits until the process has ended and the port is free. Idempotent. */
    synchronized void stop() {
        Process p = process;
        process = null;
        if (p == null) {
            return;
        }
        p.destroy();
        try {
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                p.waitFor(10, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
        }
        // the port must be free again before a restart binds it
        Instant deadline = Instant.now().plusSeconds(10);
        while (accepts() && Instant.now().isBefore(deadline)) {
            sleep(50);
        }
    }

    /** SIGKILL: no orderly shutdown. */
    synchronized void kill() {
        Process p = process;
        process = null;
        if (p != null) {
            p.destroyForcibly();
            try {
                p.waitFor(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    synchronized boolean isRunning() {
        return process != null && process.isAlive();
    }

    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            s.setReuseAddress(true);
            return s.getLocalPort();
        }
    }

    static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        }
    }
}

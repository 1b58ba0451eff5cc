package org.tinysep.launcher;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * systemd's notification protocol (sd_notify) for {@code Type=notify} and {@code WatchdogSec} in
 * {@code dist/systemd/tinysep.service}. Java 17 has Unix domain sockets for streams only ({@code SocketChannel}),
 * not for datagrams, and {@code $NOTIFY_SOCKET} is a datagram socket; so each message goes through systemd's own
 * {@code systemd-notify --pid=<this JVM> …} (the unit sets {@code NotifyAccess=all}, since the sender is a child
 * process). Active only when systemd set {@code NOTIFY_SOCKET}; a failure is logged once and never stops TinySEP.
 */
final class SdNotify {

    static final String SOCKET_ENV = "NOTIFY_SOCKET";
    static final String WATCHDOG_ENV = "WATCHDOG_USEC";
    private static final Logger LOG = LoggerFactory.getLogger(SdNotify.class);

    private final String command;
    private final Map<String, String> env;
    private final long pid = ProcessHandle.current().pid();
    private volatile boolean warned;

    private SdNotify(String command, Map<String, String> env) {
        this.command = command;
        this.env = env;
    }

    /** @return a notifier when systemd asked for notifications ({@value #SOCKET_ENV} set), else empty */
    static Optional<SdNotify> fromEnvironment(Map<String, String> env) {
        String socket = env.get(SOCKET_ENV);
        if (socket == null || socket.isBlank()) {
            return Optional.empty();
        }
        return Optional.of(new SdNotify(System.getProperty("tinysep.sdnotify.command", "systemd-notify"),
                Map.of(SOCKET_ENV, socket)));
    }

    /** @return half of systemd's watchdog interval ({@value #WATCHDOG_ENV}), the rate it asks to be fed at */
    static Optional<Duration> watchdogInterval(Map<String, String> env) {
        try {
            long usec = Long.parseLong(env.getOrDefault(WATCHDOG_ENV, "").strip());
            return usec > 0 ? Optional.of(Duration.ofNanos(usec * 1000 / 2)) : Optional.empty();
        } catch (NumberFormatException e) {
            return Optional.empty();
        }
    }

    void ready(String status) {
        send("READY=1", "STATUS=" + status);
    }

    void watchdog() {
        send("WATCHDOG=1");
    }

    void stopping() {
        send("STOPPING=1");
    }

    /** @return whether {@code systemd-notify} took the message */
    boolean send(String... assignments) {
        List<String> cmd = new ArrayList<>(List.of(command, "--pid=" + pid));
        cmd.addAll(List.of(assignments));
        try {
            ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD);
            pb.environment().putAll(env);
            Process p = pb.start();
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return problem("systemd-notify did not answer within 10 s");
            }
            return p.exitValue() == 0 || problem("systemd-notify " + String.join(" ", assignments)
                    + " ended with exit code " + p.exitValue());
        } catch (IOException e) {
            return problem("cannot run " + command + ": " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    private boolean problem(String what) {
        if (!warned) {
            warned = true;
            LOG.warn("Cannot notify systemd: {}; systemd's watchdog may restart TinySEP", what);
        }
        return false;
    }
}

package org.tinysep.launcher;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.device.support.time.Backoff;

/**
 * {@code java -jar tinysep.jar --supervise …}: the same guarantee as systemd's {@code Restart=on-failure} and
 * {@code WatchdogSec} without systemd. Runs the platform as a child process ({@code --daemon}, same JVM options and
 * arguments), watches its heartbeat file ({@link HeartbeatFile}) and restarts it when it ends with an error or stops
 * responding: no heartbeat within {@code tinysep.supervisor.hangSeconds} (default 90 s) once it has beaten, or
 * within {@code tinysep.supervisor.startSeconds} (default 300 s) of its start. A hung child is killed (SIGKILL).
 * Before the restart it leaves a {@link RestartNote}, so the new platform records and mails what happened. Exit code
 * 0 (a clean stop) or 2 (a bad argument) ends the supervisor too; SIGTERM to the supervisor stops the child cleanly.
 */
final class Supervisor {

    static final String HANG_PROPERTY = "tinysep.supervisor.hangSeconds";
    static final String START_PROPERTY = "tinysep.supervisor.startSeconds";
    private static final Logger LOG = LoggerFactory.getLogger(Supervisor.class);
    private static final Duration POLL = Duration.ofMillis(500);
    private static final Duration MAX_BACKOFF = Duration.ofSeconds(60);

    private final Path var;
    private final List<String> childArgs;
    private final Duration hang = Duration.ofSeconds(Long.getLong(HANG_PROPERTY, 90));
    private final Duration startLimit = Duration.ofSeconds(Long.getLong(START_PROPERTY, 300));
    private volatile boolean stopping;
    private volatile Process child;

    /**
     * @param var  the state folder (where the child's heartbeat is)
     * @param args the launcher's arguments without {@code --supervise}
     */
    Supervisor(Path var, List<String> args) {
        this.var = var;
        this.childArgs = new ArrayList<>(args);
        if (!childArgs.contains("--daemon") && !childArgs.contains("-d")) {
            childArgs.add("--daemon");
        }
    }

    /** Supervises until the platform stops cleanly or the supervisor is stopped; @return the exit code */
    int run(Path launcherJar) throws InterruptedException {
        Runtime.getRuntime().addShutdownHook(new Thread(this::stopChild, "tinysep-supervisor-stop"));
        Backoff backoff = Backoff.of(Duration.ofSeconds(1), MAX_BACKOFF); // 1, 2, 4 … 60 s
        while (!stopping) {
            Instant started = Instant.now();
            Process p;
            try {
                p = start(launcherJar);
            } catch (IOException e) {
                LOG.error("Supervisor: cannot start the platform: {}", e.toString());
                return 1;
            }
            System.out.println("Supervisor: TinySEP started as process " + p.pid());
            Optional<RestartNote> failure = watch(p, started);
            if (failure.isEmpty()) {
                return p.exitValue(); // 0: stopped cleanly; 2: bad argument; or the supervisor is stopping
            }
            try {
                failure.get().write(var);
            } catch (IOException e) {
                LOG.warn("Supervisor: cannot write {}: {}", RestartNote.FILE, e.toString());
            }
            if (Duration.between(started, Instant.now()).compareTo(MAX_BACKOFF.multipliedBy(5)) > 0) {
                backoff = backoff.reset(); // it ran a good while: not a crash loop
            }
            backoff = backoff.failed();
            System.out.println("Supervisor: TinySEP " + failure.get().cause() + " at " + failure.get().at()
                    + "; restarting it in " + backoff.delaySeconds() + " s");
            Thread.sleep(backoff.delay().toMillis());
        }
        return 0;
    }

    /** @return why the child must be restarted, or empty when it ended as it should (or we are stopping) */
    private Optional<RestartNote> watch(Process p, Instant started) throws InterruptedException {
        while (true) {
            if (p.waitFor(POLL.toMillis(), TimeUnit.MILLISECONDS)) {
                int code = p.exitValue();
                return stopping || code == 0 || code == 2 ? Optional.empty() : Optional.of(RestartNote.exited(code));
            }
            Optional<HeartbeatFile.Beat> beat = HeartbeatFile.read(var)
                    .filter(b -> b.pid() == p.pid() && "RUNNING".equals(b.state())); // STARTING: not beating yet
            Instant now = Instant.now();
            boolean hung = beat.isPresent() ? beat.get().alive().plus(hang).isBefore(now)
                    : started.plus(startLimit).isBefore(now);
            if (hung && !stopping) {
                Instant last = beat.map(HeartbeatFile.Beat::alive).orElse(started);
                LOG.warn("Supervisor: TinySEP (process {}) stopped responding: no heartbeat since {}; killing it",
                        p.pid(), last);
                p.destroyForcibly();
                p.waitFor();
                return Optional.of(new RestartNote(RestartNote.HUNG, last));
            }
        }
    }

    private Process start(Path launcherJar) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(ManagementFactory.getRuntimeMXBean().getInputArguments());
        cmd.add("-jar");
        cmd.add(launcherJar.toString());
        cmd.addAll(childArgs);
        Process p = new ProcessBuilder(cmd).inheritIO().start();
        child = p;
        return p;
    }

    /** SIGTERM to the child (its shutdown hook stops the framework cleanly), then wait for it. */
    private void stopChild() {
        stopping = true;
        Process p = child;
        if (p != null && p.isAlive()) {
            p.destroy();
            try {
                if (!p.waitFor(40, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}

package org.tinysep.launcher;

import java.io.IOException;
import java.time.Duration;
import java.time.Instant;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Feeds the watchdogs only while the platform is really alive: every {@code interval} the {@link LivenessProbe}
 * runs (on its own thread, limited to one interval); when it passes, the heartbeat file gets the time (for the
 * supervisor) and systemd gets {@code WATCHDOG=1}. When it fails or hangs, nothing is fed, so the supervisor or
 * systemd restarts the platform; one WARN says why.
 */
final class Heartbeat implements AutoCloseable {

    /** System property: seconds between liveness checks (default {@value #DEFAULT_SECONDS}). */
    static final String INTERVAL_PROPERTY = "tinysep.heartbeat.seconds";
    static final long DEFAULT_SECONDS = 10;
    private static final Logger LOG = LoggerFactory.getLogger(Heartbeat.class);

    /** One liveness check: returns when the platform answers, throws saying what does not. */
    interface Probe {
        void check() throws Exception;

        /** @return whether a clean stop is under way (then a failed check is no news) */
        default boolean stopping() {
            return false;
        }
    }

    private final Probe probe;
    private final HeartbeatFile file;
    private final Optional<SdNotify> systemd;
    private final Duration interval;
    private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(
            r -> daemon(r, "tinysep-heartbeat"));
    private final ExecutorService prober = Executors.newSingleThreadExecutor(r -> daemon(r, "tinysep-liveness"));
    private Future<?> running;
    private volatile boolean failing;

    Heartbeat(Probe probe, HeartbeatFile file, Optional<SdNotify> systemd, Duration interval) {
        this.probe = probe;
        this.file = file;
        this.systemd = systemd;
        this.interval = interval;
    }

    static Duration interval(Optional<Duration> systemdAsks) {
        Duration configured = Duration.ofSeconds(Long.getLong(INTERVAL_PROPERTY, DEFAULT_SECONDS));
        Duration chosen = systemdAsks.filter(d -> d.compareTo(configured) < 0).orElse(configured);
        return chosen.isZero() || chosen.isNegative() ? Duration.ofSeconds(1) : chosen;
    }

    void start() {
        timer.scheduleWithFixedDelay(this::beat, 0, interval.toMillis(), TimeUnit.MILLISECONDS);
    }

    private void beat() {
        if (running != null && !running.isDone()) {
            fail("the liveness check started " + interval.toSeconds() + " s ago has not come back");
            return;
        }
        running = prober.submit(() -> {
            probe.check();
            return null;
        });
        try {
            running.get(interval.toMillis(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            fail("the liveness check did not come back within " + interval.toSeconds() + " s");
            return;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        } catch (Exception e) {
            if (e.getCause() instanceof LivenessProbe.Stopping) {
                return; // a clean stop under way: no beat, no warning
            }
            fail(Failures.describe(e.getCause() == null ? e : e.getCause()));
            return;
        }
        try {
            file.write("RUNNING", Instant.now());
        } catch (IOException e) {
            LOG.warn("Cannot write the heartbeat file: {}", e.toString());
        }
        systemd.ifPresent(SdNotify::watchdog);
        if (failing) {
            failing = false;
            LOG.info("TinySEP answers again; the heartbeat goes on");
        }
    }

    private void fail(String why) {
        if (!failing && !probe.stopping()) {
            failing = true;
            LOG.warn("TinySEP is not responding ({}): the heartbeat stops, so the supervisor or systemd restarts it",
                    why);
        }
    }

    /** @return whether the last check failed or hung (the heartbeat is stopped) */
    boolean failing() {
        return failing;
    }

    @Override
    public void close() {
        timer.shutdownNow();
        prober.shutdownNow();
    }

    private static Thread daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }
}

package org.tinysep.serial.support;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The read side of a {@link SerialPortLink}: on one single-thread executor it opens the port, reads it (one
 * blocking read with a timeout per task, so closing never waits long), and after a failed open or a lost port
 * tries again every {@code reopenEvery}. All listener calls happen on that thread.
 */
final class PortReader {

    static final int READ_TIMEOUT_MS = 200;
    static final int WRITE_TIMEOUT_MS = 1000;
    private static final Logger LOG = LoggerFactory.getLogger(PortReader.class);

    private final String portPath;
    private final int baudRate;
    private final Duration reopenEvery;
    private final String name;
    private final SerialPortLink.Listener listener;
    private final ScheduledThreadPoolExecutor executor;
    private final byte[] buf = new byte[4096];
    private final AtomicLong bytesRead = new AtomicLong();
    private volatile PortHandle port;
    private volatile boolean closed;
    private volatile String state = "not started";
    private boolean outageReported; // read thread only

    PortReader(String portPath, int baudRate, Duration reopenEvery, String name, SerialPortLink.Listener listener) {
        this.portPath = portPath;
        this.baudRate = baudRate;
        this.reopenEvery = reopenEvery;
        this.name = name;
        this.listener = listener;
        this.executor = new ScheduledThreadPoolExecutor(1, r -> SerialPortLink.daemon(r, name + "-read"));
        this.executor.setExecuteExistingDelayedTasksAfterShutdownPolicy(false);
    }

    void start() {
        state = "opening";
        schedule(this::openOrRetry, Duration.ZERO);
    }

    private void openOrRetry() {
        if (closed) {
            return;
        }
        String problem;
        if (!Files.exists(Path.of(portPath))) {
            problem = "no such port";
        } else {
            PortHandle.Opening attempt = PortHandle.open(portPath, baudRate, READ_TIMEOUT_MS, WRITE_TIMEOUT_MS);
            if (attempt.handle() != null) {
                opened(attempt.handle());
                return;
            }
            problem = attempt.problem();
        }
        state = "missing (" + problem + "), retrying every " + seconds(reopenEvery);
        if (!outageReported) {
            outageReported = true;
            LOG.warn("{}: cannot open {}: {}; retrying every {}", name, portPath, problem, seconds(reopenEvery));
            report(() -> listener.lost(portPath, "cannot open: " + problem));
        }
        schedule(this::openOrRetry, reopenEvery);
    }

    private void opened(PortHandle handle) {
        port = handle;
        outageReported = false;
        state = "open at " + baudRate + " baud";
        LOG.info("{}: opened {} ({}) at {} baud", name, portPath, handle.devicePath(), baudRate);
        report(() -> listener.opened(portPath));
        schedule(this::readOnce, Duration.ZERO);
    }

    private void readOnce() {
        PortHandle p = port;
        if (closed || p == null) {
            return;
        }
        int n = p.read(buf);
        if (n < 0) {
            lost(p, "read failed: the port vanished or its peer went away");
            return;
        }
        if (n > 0) {
            bytesRead.addAndGet(n);
            report(() -> listener.bytes(buf, n));
        }
        schedule(this::readOnce, Duration.ZERO);
    }

    private void lost(PortHandle p, String reason) {
        port = null;
        p.close();
        if (closed) {
            return;
        }
        outageReported = true;
        state = "lost (" + reason + "), reopening every " + seconds(reopenEvery);
        LOG.warn("{}: lost {}: {}; reopening every {}", name, portPath, reason, seconds(reopenEvery));
        report(() -> listener.lost(portPath, reason));
        schedule(this::openOrRetry, reopenEvery);
    }

    private void report(Runnable call) {
        try {
            call.run();
        } catch (RuntimeException e) {
            LOG.error("{}: a listener of {} failed; the link goes on", name, portPath, e);
        }
    }

    private void schedule(Runnable task, Duration delay) {
        try {
            executor.schedule(task, delay.toMillis(), TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException e) {
            // closing
        }
    }

    /** @return the open port, or null */
    PortHandle port() {
        PortHandle p = port;
        return closed ? null : p;
    }

    String state() {
        return state;
    }

    long bytesRead() {
        return bytesRead.get();
    }

    /** Stops the read thread (waiting at most a few read timeouts), then closes the port. */
    void close() {
        closed = true;
        state = "closed";
        executor.shutdown();
        try {
            if (!executor.awaitTermination(READ_TIMEOUT_MS * 10L, TimeUnit.MILLISECONDS)) {
                executor.shutdownNow();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        PortHandle p = port;
        port = null;
        if (p != null) {
            p.close();
        }
    }

    static String seconds(Duration d) {
        return d.toMillis() % 1000 == 0 ? d.toSeconds() + " s" : d.toMillis() + " ms";
    }
}

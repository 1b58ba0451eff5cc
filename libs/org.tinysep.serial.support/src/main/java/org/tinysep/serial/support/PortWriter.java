package org.tinysep.serial.support;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The write side of a {@link SerialPortLink}: a single-thread executor with a bounded queue, so a caller never
 * blocks; a write while the port is closed, or with the queue full, is dropped and counted.
 */
final class PortWriter {

    static final int MAX_QUEUED_WRITES = 1000;
    private static final Logger LOG = LoggerFactory.getLogger(PortWriter.class);

    private final String name;
    private final Supplier<PortHandle> port;
    private final Supplier<String> state;
    private final ExecutorService executor;
    private final AtomicLong bytesWritten = new AtomicLong();
    private final AtomicLong failures = new AtomicLong();

    /**
     * @param port  the open port, or null while there is none
     * @param state the link's state, for failure messages
     */
    PortWriter(String name, Supplier<PortHandle> port, Supplier<String> state) {
        this.name = name;
        this.port = port;
        this.state = state;
        this.executor = new ThreadPoolExecutor(1, 1, 0, TimeUnit.MILLISECONDS,
                new LinkedBlockingQueue<>(MAX_QUEUED_WRITES), r -> SerialPortLink.daemon(r, name + "-write"));
    }

    void write(byte[] data, SerialPortLink.WriteResult result) {
        if (port.get() == null) {
            failed(data, result, notOpen());
            return;
        }
        try {
            executor.execute(() -> writeNow(data, result));
        } catch (RejectedExecutionException e) {
            failed(data, result, executor.isShutdown() ? "not sent: link closed" : "not sent: write queue full");
        }
    }

    private void writeNow(byte[] data, SerialPortLink.WriteResult result) {
        PortHandle p = port.get();
        if (p == null) {
            failed(data, result, notOpen());
            return;
        }
        int n = p.write(data);
        if (n == data.length) {
            bytesWritten.addAndGet(n);
            tell(result, data, null);
        } else {
            failed(data, result, "write failed: " + Math.max(n, 0) + " of " + data.length + " bytes written");
        }
    }

    private String notOpen() {
        return "not sent: port is not open (" + state.get() + ")";
    }

    private void failed(byte[] data, SerialPortLink.WriteResult result, String why) {
        failures.incrementAndGet();
        tell(result, data, why);
    }

    private void tell(SerialPortLink.WriteResult result, byte[] data, String failure) {
        try {
            result.done(data, failure);
        } catch (RuntimeException e) {
            LOG.error("{}: a write callback failed", name, e);
        }
    }

    long bytesWritten() {
        return bytesWritten.get();
    }

    long failures() {
        return failures.get();
    }

    /** Finishes queued writes (bounded by the write timeout), then stops. */
    void close() {
        executor.shutdown();
        try {
            if (!executor.awaitTermination(PortReader.WRITE_TIMEOUT_MS * 2L, TimeUnit.MILLISECONDS)) {
                executor.shutdownNow();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

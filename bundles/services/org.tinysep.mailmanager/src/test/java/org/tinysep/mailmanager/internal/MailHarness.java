package org.tinysep.mailmanager.internal;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.service.MailStatus;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/** Builds Mail Manager devices outside a framework, records their events and captures System.err (slf4j-simple). */
final class MailHarness implements AutoCloseable {

    final RecordingLogs logs = new RecordingLogs(Instant::now);
    final List<MailStatus> statuses = new CopyOnWriteArrayList<>();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private final PrintStream originalErr = System.err;
    private MailManagerDevice device;

    MailHarness() {
        PrintStream tee = new PrintStream(new OutputStream() {
            @Override
            public synchronized void write(int b) {
                err.write(b);
                originalErr.write(b);
            }

            @Override
            public synchronized void write(byte[] b, int off, int len) {
                err.write(b, off, len);
                originalErr.write(b, off, len);
            }
        }, true, StandardCharsets.UTF_8);
        System.setErr(tee);
    }

    static Map<String, Object> smtp(int port, Path spool) {
        Map<String, Object> c = new HashMap<>();
        c.put("host", "127.0.0.1");
        c.put("port", port);
        c.put("security", "NONE");
        c.put("from", "tinysep@home.test");
        c.put("recipients", "carer@care.test, family@kin.test");
        c.put("connectTimeoutSeconds", 2);
        c.put("retryInitialSeconds", 1);
        c.put("retryMaxSeconds", 2);
        c.put("spoolDir", spool.toString());
        return c;
    }

    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    /** Starts a device (closing the previous one, as a component restart would). */
    MailManagerDevice start(Map<String, Object> config) {
        stopDevice();
        DriverContext ctx = new DriverContext(null, "driver-uid", MailManagerDriver.NAME, logs.reporter(),
                new PlatformClock(Instant::now));
        device = new MailManagerDevice(ctx, MailSettings.parse(config, null), null, new SmtpTransport());
        device.provider().connect((src, status, at) -> statuses.add(status));
        return device;
    }

    void stopDevice() {
        if (device != null) {
            device.onDispose();
            device = null;
        }
    }

    String stderr() {
        synchronized (err) {
            return err.toString(StandardCharsets.UTF_8);
        }
    }

    List<String> eventTexts() {
        return logs.events().stream().map(EventEntry::message).toList();
    }

    static void await(String what, BooleanSupplier condition) {
        long deadline = System.nanoTime() + Duration.ofSeconds(20).toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out waiting for " + what);
            }
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError("interrupted waiting for " + what);
            }
        }
    }

    @Override
    public void close() {
        stopDevice();
        System.setErr(originalErr);
    }
}

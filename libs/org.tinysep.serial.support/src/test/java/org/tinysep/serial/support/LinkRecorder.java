package org.tinysep.serial.support;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/** Records what the link reports: "opened <port>" / "lost <port>: <reason>" in order, and the bytes. */
final class LinkRecorder implements SerialPortLink.Listener {

    final BlockingQueue<String> events = new LinkedBlockingQueue<>();
    final List<String> all = new CopyOnWriteArrayList<>();
    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();

    @Override
    public synchronized void bytes(byte[] buf, int len) {
        bytes.write(buf, 0, len);
    }

    @Override
    public void opened(String port) {
        record("opened " + port);
    }

    @Override
    public void lost(String port, String reason) {
        record("lost " + port + ": " + reason);
    }

    private void record(String event) {
        all.add(event);
        events.add(event);
    }

    synchronized byte[] bytes() {
        return bytes.toByteArray();
    }

    String next() throws InterruptedException {
        String e = events.poll(10, TimeUnit.SECONDS);
        if (e == null) {
            fail("no link event within 10 s; so far " + all);
        }
        return e;
    }
}

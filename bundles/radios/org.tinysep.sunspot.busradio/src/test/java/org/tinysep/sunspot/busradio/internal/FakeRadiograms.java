package org.tinysep.sunspot.busradio.internal;

import java.io.IOException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * An in-process stand-in for the Sun SPOT SDK behind the {@link RadiogramSource} seam: tests put radiograms (or
 * failures) into a queue, the link receives them. Every {@link #open(int)} creates a fresh source, as the SDK
 * would open a fresh connection; {@link #failOpens} makes the next opens fail.
 */
final class FakeRadiograms implements RadiogramSource.Opener {

    private static final Radiogram CLOSED = new Radiogram("closed", new byte[0]);
    private static final Radiogram FAIL = new Radiogram("fail", new byte[0]);

    final AtomicInteger opens = new AtomicInteger();
    final AtomicInteger failOpens = new AtomicInteger();
    volatile int openedPort = -1;
    private volatile Source current;

    @Override
    public RadiogramSource open(int port) throws IOException {
        opens.incrementAndGet();
        if (failOpens.getAndUpdate(n -> Math.max(0, n - 1)) > 0) {
            throw new IOException("no basestation on the serial port");
        }
        openedPort = port;
        Source s = new Source();
        current = s;
        return s;
    }

    /** Delivers a radiogram to the currently open source. */
    void send(String address, byte[] data) {
        current.queue.add(new Radiogram(address, data));
    }

    /** Makes the current source's receive fail, as an unplugged basestation would. */
    void breakConnection() {
        current.queue.add(FAIL);
    }

    boolean isOpen() {
        Source s = current;
        return s != null && !s.closed;
    }

    private static final class Source implements RadiogramSource {
        final LinkedBlockingQueue<Radiogram> queue = new LinkedBlockingQueue<>();
        volatile boolean closed;

        @Override
        public Radiogram receive() throws IOException {
            Radiogram r;
            try {
                r = queue.take();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted");
            }
            if (r == CLOSED) {
                throw new IOException("connection closed");
            }
            if (r == FAIL) {
                throw new IOException("basestation unplugged");
            }
            return r;
        }

        @Override
        public void close() {
            closed = true;
            queue.add(CLOSED);
        }
    }
}

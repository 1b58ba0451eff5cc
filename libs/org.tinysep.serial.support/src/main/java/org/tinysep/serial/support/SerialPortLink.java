package org.tinysep.serial.support;

import java.time.Duration;
import java.util.Objects;

/**
 * One serial port, kept open: {@link #start()} opens it by path and reads it on the link's own single-thread
 * executor (blocking reads with a timeout); while the port is missing, or after it was lost, the link tries to
 * open it again every {@code reopenEvery}, by itself, until {@link #close()}. Writes are queued on a second
 * single-thread executor and never block the caller; while the port is closed they are dropped and counted.
 * <p>
 * Lost means a read returned -1 or failed: that is how a vanished pseudo-terminal or an unplugged USB adapter
 * shows (jSerialComm's {@code isOpen()} stays true then). DTR/RTS are left alone: they fail on a pseudo-terminal.
 * <p>
 * All {@link Listener} calls come from the read thread, in order; a listener that throws is logged and the link
 * goes on.
 */
public final class SerialPortLink implements AutoCloseable {

    /** What the link reports; called on the link's read thread. */
    public interface Listener {
        /** Bytes read; {@code buf} is reused after the call returns. */
        void bytes(byte[] buf, int len);

        /** The port is open (the first time or again). */
        void opened(String port);

        /**
         * The port could not be opened or was lost: called once per outage (the first failed open counts as
         * one); the link keeps trying by itself and calls {@link #opened(String)} when it succeeds.
         */
        void lost(String port, String reason);
    }

    /** Told the outcome of one write, on the write thread (or on the caller's when dropped at once). */
    public interface WriteResult {
        /** @param failure null when every byte was written, otherwise why not */
        void done(byte[] data, String failure);
    }

    private final String portPath;
    private final int baudRate;
    private final PortReader reader;
    private final PortWriter writer;
    private boolean started;
    private boolean closed;

    /**
     * @param portPath    e.g. {@code /dev/ttyUSB0} or a socat {@code link=} path; opened by path at every attempt,
     *                    so a link that points to a new device after a reconnect is followed
     * @param baudRate    bits per second, 8 data bits, no parity, one stop bit, no flow control
     * @param reopenEvery pause between attempts to open a missing or lost port
     * @param name        names the link's threads and log lines
     * @throws IllegalArgumentException if the baud rate or the pause is not positive
     */
    public SerialPortLink(String portPath, int baudRate, Duration reopenEvery, String name, Listener listener) {
        this.portPath = Objects.requireNonNull(portPath, "portPath");
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(listener, "listener");
        if (baudRate <= 0) {
            throw new IllegalArgumentException("baud rate must be positive, was " + baudRate);
        }
        if (reopenEvery == null || reopenEvery.isNegative() || reopenEvery.isZero()) {
            throw new IllegalArgumentException("reopenEvery must be positive, was " + reopenEvery);
        }
        this.baudRate = baudRate;
        this.reader = new PortReader(portPath, baudRate, reopenEvery, name, listener);
        this.writer = new PortWriter(name, reader::port, reader::state);
    }

    static Thread daemon(Runnable r, String threadName) {
        Thread t = new Thread(r, threadName);
        t.setDaemon(true);
        return t;
    }

    /** Opens the port and starts reading, on the link's thread; returns at once. Calling it again does nothing. */
    public synchronized void start() {
        if (started || closed) {
            return;
        }
        started = true;
        reader.start();
    }

    /** Queues bytes for the port; never blocks. Dropped and counted while the port is not open. */
    public void write(byte[] data) {
        write(data, (d, failure) -> { });
    }

    /** Like {@link #write(byte[])}, telling {@code result} the outcome. */
    public void write(byte[] data, WriteResult result) {
        writer.write(data.clone(), Objects.requireNonNull(result, "result"));
    }

    /** @return whether the port is open now (a lost port counts as closed at once) */
    public boolean isOpen() {
        return reader.port() != null;
    }

    /** Stops reading, writing and reopening, and closes the port; waits briefly for the threads to end. */
    @Override
    public void close() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
        }
        writer.close(); // first, so writes already queued still reach the port
        reader.close();
    }

    public String portPath() {
        return portPath;
    }

    public int baudRate() {
        return baudRate;
    }

    /** @return the link's state for the user, e.g. {@code open at 115200 baud} or {@code lost (...), reopening ...} */
    public String state() {
        return reader.state();
    }

    public long bytesRead() {
        return reader.bytesRead();
    }

    public long bytesWritten() {
        return writer.bytesWritten();
    }

    /** @return writes dropped (port not open, queue full) or failed */
    public long writeFailures() {
        return writer.failures();
    }

    /** @return the port path, e.g. {@code /dev/ttyUSB0}: how the link reads in parameters and logs */
    @Override
    public String toString() {
        return portPath;
    }
}

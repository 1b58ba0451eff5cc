package org.tinysep.sunspot.busradio.internal;

import java.time.Duration;
import org.tinysep.api.log.EventKind;
import org.tinysep.serial.support.SerialPortLink;
import org.tinysep.sunspot.protocol.RejectReason;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotStreamDecoder;

/**
 * The serial link: a basestation whose firmware writes framed Sun SPOT packets to USB. The port is kept open (and
 * reopened) by a {@link SerialPortLink}; its bytes go through a {@link SunSpotStreamDecoder} to the shared
 * {@link PacketHandler}, all on the link's read thread. Skipped byte runs are counted and logged like rejected
 * packets. When the port is lost, the decoder's partial frame is reported and dropped, and the nodes last heard
 * here go OFFLINE until their next packet.
 */
final class SerialLink implements AutoCloseable, SerialPortLink.Listener, SunSpotStreamDecoder.Sink {

    private static final byte[] NO_BYTES = new byte[0];

    private final Feed feed;
    private final String name;
    private final SunSpotStreamDecoder decoder = new SunSpotStreamDecoder(this);
    private final SerialPortLink port;

    SerialLink(String portPath, int baudRate, Duration reopenEvery, Feed feed) {
        this.feed = feed;
        this.name = "serial " + portPath;
        this.port = new SerialPortLink(portPath, baudRate, reopenEvery, feed.context().driverName() + "-serial", this);
    }

    /** Opens the port and reads it on the link's own thread; returns at once. */
    void start() {
        port.start();
    }

    @Override
    public void bytes(byte[] buf, int len) {
        decoder.accept(buf, 0, len);
    }

    @Override
    public void opened(String portPath) {
        feed.context().event(EventKind.STATUS, name + " open at " + port.baudRate() + " baud");
    }

    @Override
    public void lost(String portPath, String reason) {
        decoder.reset();
        feed.nodes().offline(name, "serial link lost: " + reason);
        feed.context().event(EventKind.PROBLEM, name + ": " + reason + "; reopening by itself");
    }

    @Override
    public void frame(SunSpotFrame f) {
        feed.handler().frame(f, SunSpotCodec.encode(f), name);
    }

    @Override
    public void rejected(RejectReason r, int skippedBytes) {
        feed.handler().rejected(r, r.name() + " (" + r.description() + "): " + skippedBytes
                + " bytes skipped in the serial stream", NO_BYTES, name);
    }

    /** @return e.g. {@code open at 115200 baud} or {@code missing (no such port), retrying every 5 s} */
    String state() {
        return port.state();
    }

    long bytesRead() {
        return port.bytesRead();
    }

    String name() {
        return name;
    }

    @Override
    public void close() {
        port.close();
    }
}

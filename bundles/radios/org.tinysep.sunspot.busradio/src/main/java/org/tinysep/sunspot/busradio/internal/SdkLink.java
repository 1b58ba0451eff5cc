package org.tinysep.sunspot.busradio.internal;

import java.io.IOException;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.link.udp.LinkThread;
import org.tinysep.sunspot.protocol.RejectReason;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;

/**
 * The SDK link: the Sun SPOT SDK running in-process receives radiograms from the basestation, each carrying one
 * Table 3.2 payload; the sender's address and the payload become a {@link SunSpotFrame} for the shared
 * {@link PacketHandler}. Opens and receives on its own {@link LinkThread}. A missing SDK is reported once
 * (status and PROBLEM event) and not retried; a port that cannot be opened or a lost connection is retried every
 * {@code reopenEvery}.
 */
final class SdkLink implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(SdkLink.class);

    private final RadiogramSource.Opener opener;
    private final int port;
    private final Duration reopenEvery;
    private final Feed feed;
    private final String name;
    private final LinkThread thread;
    private final AtomicLong unreadable = new AtomicLong();
    private volatile RadiogramSource source;
    private volatile boolean closed;
    private volatile String state = "not started";
    private boolean outageReported; // executor thread only

    SdkLink(RadiogramSource.Opener opener, int port, Duration reopenEvery, Feed feed) {
        this.opener = opener;
        this.port = port;
        this.reopenEvery = reopenEvery;
        this.feed = feed;
        this.name = "sdk radiogram://:" + port;
        this.thread = new LinkThread(feed.context().driverName() + "-sdk");
    }

    /** Opens the radiogram port and receives, on the link's thread; returns at once. */
    void start() {
        state = "opening " + name;
        thread.schedule(this::openAndReceive, Duration.ZERO);
    }

    private void openAndReceive() {
        RadiogramSource s;
        try {
            s = opener.open(port);
        } catch (SdkUnavailableException e) {
            state = e.getMessage();
            problem(e.getMessage() + "; the SDK link is off, the other links are not affected (docs/sunspot-sdk.md)");
            return;
        } catch (IOException | RuntimeException e) {
            outage("cannot open " + name + ": " + e.getMessage());
            return;
        }
        source = s;
        if (closed) {
            s.close();
            return;
        }
        outageReported = false;
        state = "receiving on " + name;
        LOG.info("{}: {}", feed.context().driverName(), state);
        receiveLoop(s);
    }

    private void receiveLoop(RadiogramSource s) {
        while (!closed) {
            Radiogram r;
            try {
                r = s.receive();
            } catch (IOException | RuntimeException e) {
                s.close();
                if (!closed) {
                    feed.nodes().offline(name, "SDK link lost");
                    outage("lost " + name + ": " + e.getMessage());
                }
                return;
            }
            try {
                radiogram(r);
            } catch (RuntimeException e) {
                LOG.error("Radiogram handling failed; the receive loop goes on", e);
            }
        }
    }

    /** Turns one radiogram into a frame for the handler, or a counted rejection. */
    void radiogram(Radiogram r) {
        byte[] data = r.data() == null ? new byte[0] : r.data();
        SunSpotAddress address;
        try {
            address = SunSpotAddress.parse(bareAddress(r.address()));
        } catch (IllegalArgumentException e) {
            if (unreadable.incrementAndGet() == 1) {
                problem("radiogram with an unreadable sender address ignored (" + e.getMessage()
                        + "); further ones are only counted");
            }
            return;
        }
        if (data.length == 0 || data.length > SunSpotCodec.MAX_PAYLOAD) {
            feed.handler().refused(new SunSpotProtocolException(data.length == 0 ? RejectReason.UNKNOWN_PAYLOAD
                    : RejectReason.OVERSIZE, data.length + "-byte radiogram from " + address), data, name);
            return;
        }
        feed.handler().frame(SunSpotFrame.of(address, data), data, name);
    }

    /** @return the dotted address without a {@code radiogram://} scheme or a {@code :port} suffix */
    static String bareAddress(String address) {
        if (address == null) {
            return null;
        }
        String a = address.startsWith("radiogram://") ? address.substring("radiogram://".length()) : address;
        int colon = a.indexOf(':');
        return colon < 0 ? a : a.substring(0, colon);
    }

    private void outage(String reason) {
        state = reason + "; retrying every " + reopenEvery.toSeconds() + " s";
        if (!outageReported) {
            outageReported = true;
            problem(reason + "; retrying every " + reopenEvery.toSeconds() + " s");
        }
        thread.schedule(this::openAndReceive, reopenEvery);
    }

    private void problem(String text) {
        LOG.warn("{}: {}", feed.context().driverName(), text);
        feed.context().event(EventKind.PROBLEM, text);
    }

    /** @return e.g. {@code receiving on sdk radiogram://:100} or {@code Sun SPOT SDK not installed (...)} */
    String state() {
        return state;
    }

    /** @return radiograms ignored because their sender address could not be read */
    long unreadable() {
        return unreadable.get();
    }

    @Override
    public void close() {
        closed = true;
        state = "closed";
        RadiogramSource s = source;
        if (s != null) {
            s.close(); // ends a blocked receive
        }
        thread.close();
    }
}

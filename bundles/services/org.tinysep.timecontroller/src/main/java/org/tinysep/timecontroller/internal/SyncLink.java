package org.tinysep.timecontroller.internal;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.link.udp.DatagramLink;

/**
 * The UDP socket of the synchroniser link, the platform's one {@link DatagramLink}: each datagram is handled
 * synchronously on its receive thread and the handler's answer goes back to the sender's address before the next
 * datagram is read, so the synchroniser sees answers in request order. A failing handler or send never ends the
 * loop.
 */
final class SyncLink implements AutoCloseable {

    /** Handles one datagram; returns the answer to send back, or null for none. */
    interface Handler {
        String datagram(byte[] data, int length, InetSocketAddress from);
    }

    private static final Logger LOG = LoggerFactory.getLogger(SyncLink.class);

    private final DatagramLink socket;

    private SyncLink(DatagramLink socket) {
        this.socket = socket;
    }

    /** Binds the socket (the system's receive buffer); datagrams wait in its buffer until {@link #start(Handler)}. */
    static SyncLink open(String bindAddress, int port) throws IOException {
        return new SyncLink(DatagramLink.open(bindAddress, port, 0, "time-sync-link"));
    }

    /** Starts handling datagrams. */
    void start(Handler handler) {
        socket.start((data, length, from) -> answer(handle(handler, data, length, from), from));
    }

    int localPort() {
        return socket.localPort();
    }

    String localAddress() {
        return socket.localAddress();
    }

    private static String handle(Handler handler, byte[] data, int length, InetSocketAddress from) {
        try {
            return handler.datagram(data, length, from);
        } catch (RuntimeException e) {
            LOG.error("Time sync datagram handling failed; the link goes on", e);
            return SyncMessage.error("-", "internal", e.toString());
        }
    }

    private void answer(String answer, InetSocketAddress to) {
        if (answer == null) {
            return;
        }
        socket.send(answer.getBytes(StandardCharsets.US_ASCII), to, (bytes, address, failure) -> {
            if (failure != null) {
                LOG.warn("Time sync answer to {} failed: {}", address, failure.toString());
            }
        });
    }

    @Override
    public void close() {
        socket.close();
    }
}

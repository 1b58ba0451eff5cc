package org.tinysep.timecontroller.internal;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The UDP socket of the synchroniser link: one receive loop on its own executor; each datagram is handled
 * synchronously on that thread and the handler's answer goes back to the sender's address before the next
 * datagram is read, so the synchroniser sees answers in request order. A failing handler or send never ends the
 * loop.
 */
final class SyncLink implements AutoCloseable {

    /** Handles one datagram; returns the answer to send back, or null for none. */
    interface Handler {
        String datagram(byte[] data, int length, InetSocketAddress from);
    }

    private static final Logger LOG = LoggerFactory.getLogger(SyncLink.class);
    /** Larger than any valid request, so an oversize one is seen as such. */
    private static final int BUFFER = 1024;

    private final DatagramSocket socket;
    private final ExecutorService receiver;
    private volatile boolean open = true;

    private SyncLink(DatagramSocket socket) {
        this.socket = socket;
        this.receiver = Executors.newSingleThreadExecutor(r -> new Thread(r, "time-sync-link"));
    }

    /** Binds the socket; datagrams wait in its buffer until {@link #start(Handler)}. */
    static SyncLink open(String bindAddress, int port) throws IOException {
        DatagramSocket socket = new DatagramSocket(null);
        try {
            socket.bind(new InetSocketAddress(InetAddress.getByName(bindAddress), port));
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
        return new SyncLink(socket);
    }

    /** Starts handling datagrams. */
    void start(Handler handler) {
        receiver.execute(() -> loop(handler));
    }

    int localPort() {
        return socket.getLocalPort();
    }

    String localAddress() {
        return socket.getLocalAddress().getHostAddress() + ":" + socket.getLocalPort();
    }

    private void loop(Handler handler) {
        byte[] buf = new byte[BUFFER];
        DatagramPacket in = new DatagramPacket(buf, buf.length);
        while (open) {
            try {
                in.setLength(buf.length);
                socket.receive(in);
            } catch (IOException e) {
                if (open) {
                    LOG.warn("Time sync receive on {} failed, continuing: {}", localAddress(), e.toString());
                }
                continue;
            }
            InetSocketAddress from = (InetSocketAddress) in.getSocketAddress();
            String answer;
            try {
                answer = handler.datagram(buf, in.getLength(), from);
            } catch (RuntimeException e) {
                LOG.error("Time sync datagram handling failed; the link goes on", e);
                answer = SyncMessage.error("-", "internal", e.toString());
            }
            if (answer != null) {
                send(answer, from);
            }
        }
    }

    private void send(String answer, InetSocketAddress to) {
        byte[] bytes = answer.getBytes(StandardCharsets.US_ASCII);
        try {
            socket.send(new DatagramPacket(bytes, bytes.length, to));
        } catch (IOException e) {
            if (open) {
                LOG.warn("Time sync answer to {} failed: {}", to, e.toString());
            }
        }
    }

    @Override
    public void close() {
        open = false;
        socket.close();
        receiver.shutdown();
        try {
            if (!receiver.awaitTermination(2, TimeUnit.SECONDS)) {
                receiver.shutdownNow();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

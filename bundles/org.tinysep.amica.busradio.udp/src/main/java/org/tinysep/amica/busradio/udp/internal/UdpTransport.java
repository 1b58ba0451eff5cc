package org.tinysep.amica.busradio.udp.internal;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The UDP socket of the driver: one receive loop on its own single-thread executor that {@link #close()} shuts
 * down; datagrams are handed to the receiver synchronously on the receive thread. Sends go out on the caller's
 * thread: a UDP send does not wait for the peer, and a command sent while the Time Controller handles a TICK is
 * then on the wire before its DONE (lock-step simulations see it in the same virtual second).
 */
final class UdpTransport implements AutoCloseable {

    /** Receives each datagram; {@code data} is reused after the call returns. */
    interface Receiver {
        void datagram(byte[] data, int length, InetSocketAddress from);
    }

    /** Told the outcome of each send. */
    interface SendResult {
        void done(byte[] frame, InetSocketAddress to, IOException failure);
    }

    private static final Logger LOG = LoggerFactory.getLogger(UdpTransport.class);
    /** Larger than any valid frame, so an oversize datagram is seen as such rather than cut silently. */
    static final int RECEIVE_BUFFER = 2048;

    private final DatagramSocket socket;
    private final ExecutorService receiveExecutor;
    private volatile boolean open = true;

    private UdpTransport(DatagramSocket socket, String name) {
        this.socket = socket;
        this.receiveExecutor = Executors.newSingleThreadExecutor(r -> new Thread(r, name + "-receive"));
    }

    /** Binds the socket; nothing is received until {@link #start(Receiver)}. */
    static UdpTransport open(String bindAddress, int port, int receiveBufferBytes, String name) throws IOException {
        DatagramSocket socket = new DatagramSocket(null);
        try {
            socket.setReceiveBufferSize(receiveBufferBytes);
            socket.bind(new InetSocketAddress(InetAddress.getByName(bindAddress), port));
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
        return new UdpTransport(socket, name);
    }

    /** Starts the receive loop; datagrams queued in the socket buffer meanwhile are not lost. */
    void start(Receiver receiver) {
        receiveExecutor.execute(() -> receiveLoop(receiver));
    }

    int localPort() {
        return socket.getLocalPort();
    }

    String localAddress() {
        return socket.getLocalAddress().getHostAddress() + ":" + socket.getLocalPort();
    }

    int receiveBufferSize() {
        try {
            return socket.getReceiveBufferSize();
        } catch (SocketException e) {
            return -1;
        }
    }

    private void receiveLoop(Receiver receiver) {
        byte[] buf = new byte[RECEIVE_BUFFER];
        DatagramPacket packet = new DatagramPacket(buf, buf.length);
        while (open) {
            try {
                packet.setLength(buf.length);
                socket.receive(packet);
            } catch (IOException e) {
                if (open) {
                    LOG.warn("UDP receive on {} failed, continuing: {}", localAddress(), e.toString());
                }
                continue;
            }
            try {
                receiver.datagram(buf, packet.getLength(), (InetSocketAddress) packet.getSocketAddress());
            } catch (RuntimeException e) {
                LOG.error("Datagram handling failed; the receive loop goes on", e);
            }
        }
    }

    /** Sends a datagram on the caller's thread and reports the outcome; a closed transport fails at once. */
    void send(byte[] frame, InetSocketAddress to, SendResult result) {
        if (!open) {
            result.done(frame, to, new IOException("bus radio is closed"));
            return;
        }
        IOException failure = null;
        try {
            socket.send(new DatagramPacket(frame, frame.length, to));
        } catch (IOException e) {
            failure = e;
        }
        result.done(frame, to, failure);
    }

    @Override
    public void close() {
        open = false;
        socket.close();
        receiveExecutor.shutdown();
        try {
            if (!receiveExecutor.awaitTermination(2, TimeUnit.SECONDS)) {
                receiveExecutor.shutdownNow();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

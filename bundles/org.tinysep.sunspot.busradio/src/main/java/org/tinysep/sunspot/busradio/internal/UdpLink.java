package org.tinysep.sunspot.busradio.internal;

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
import org.tinysep.device.support.SourceGate;

/**
 * The UDP link: one Sun SPOT frame per datagram, from simulators or from a forwarding program next to the
 * basestation (the thesis prototype's way). One receive loop on its own single-thread executor, which
 * {@link #close()} shuts down; datagrams go to the {@link PacketHandler} synchronously on that thread.
 */
final class UdpLink implements AutoCloseable {

    /** Receive buffer of the socket (DESIGN.md: the default one drops packets during millisecond stalls). */
    static final int SOCKET_BUFFER = 4 * 1024 * 1024;
    /** Larger than any valid frame, so an oversize datagram is seen as such rather than cut silently. */
    static final int DATAGRAM_BUFFER = 2048;
    private static final Logger LOG = LoggerFactory.getLogger(UdpLink.class);

    private final DatagramSocket socket;
    private final ExecutorService receiver;
    private volatile boolean open = true;
    private volatile SourceGate gate;
    private volatile java.util.function.Consumer<String> problems = p -> { };

    private UdpLink(DatagramSocket socket, String name) {
        this.socket = socket;
        this.receiver = Executors.newSingleThreadExecutor(r -> new Thread(r, name + "-udp"));
    }

    /** Binds the socket; nothing is received until {@link #start(PacketHandler)}. */
    static UdpLink open(String bindAddress, int port, String name) throws IOException {
        DatagramSocket socket = new DatagramSocket(null);
        try {
            socket.setReceiveBufferSize(SOCKET_BUFFER);
            socket.bind(new InetSocketAddress(InetAddress.getByName(bindAddress), port));
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
        return new UdpLink(socket, name);
    }

    /**
     * Sets who may send (docs/security.md); call before {@link #start}.
     *
     * @param problems told the first refusal of each kind, for the event log
     */
    void gate(SourceGate gate, java.util.function.Consumer<String> problems) {
        this.gate = gate;
        this.problems = problems;
    }

    /** Starts the receive loop; datagrams queued in the socket buffer meanwhile are not lost. */
    void start(PacketHandler handler) {
        receiver.execute(() -> receiveLoop(handler));
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

    private void receiveLoop(PacketHandler handler) {
        byte[] buf = new byte[DATAGRAM_BUFFER];
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
            String from = "udp " + packet.getAddress().getHostAddress() + ":" + packet.getPort();
            SourceGate g = gate;
            SourceGate.Verdict verdict = g == null ? SourceGate.Verdict.PASS : g.check(packet.getAddress());
            if (verdict != SourceGate.Verdict.PASS) {
                String first = g.firstRefusal(verdict, packet.getAddress());
                if (first != null) {
                    LOG.warn("UDP link {}: {}", localAddress(), first);
                    problems.accept(first);
                }
                handler.refusedSource(SourceGate.why(verdict, packet.getAddress()), buf, packet.getLength(), from);
                continue;
            }
            try {
                handler.datagram(buf, packet.getLength(), from);
            } catch (RuntimeException e) {
                LOG.error("Datagram handling failed; the receive loop goes on", e);
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

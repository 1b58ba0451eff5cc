package org.tinysep.sunspot.busradio.internal;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.device.support.intake.SourceGate;
import org.tinysep.link.udp.DatagramLink;

/**
 * The UDP link: one Sun SPOT frame per datagram, from simulators or from a forwarding program next to the
 * basestation (the thesis prototype's way). The socket and its receive loop are the platform's one
 * {@link DatagramLink}; this link adds the source gate and hands each datagram to the {@link PacketHandler}
 * synchronously on the receive thread.
 */
final class UdpLink implements AutoCloseable {

    /**
     * Receive buffer of the socket (docs/architecture.md "Threading": the default one drops packets during
     * millisecond stalls).
     */
    static final int SOCKET_BUFFER = 4 * 1024 * 1024;
    private static final Logger LOG = LoggerFactory.getLogger(UdpLink.class);

    private final DatagramLink socket;
    private volatile SourceGate gate;
    private volatile Consumer<String> problems = p -> { };

    private UdpLink(DatagramLink socket) {
        this.socket = socket;
    }

    /** Binds the socket; nothing is received until {@link #start(PacketHandler)}. */
    static UdpLink open(String bindAddress, int port, String name) throws IOException {
        return new UdpLink(DatagramLink.open(bindAddress, port, SOCKET_BUFFER, name + "-udp"));
    }

    /**
     * Sets who may send (docs/security.md); call before {@link #start}.
     *
     * @param problems told the first refusal of each kind, for the event log
     */
    void gate(SourceGate gate, Consumer<String> problems) {
        this.gate = gate;
        this.problems = problems;
    }

    /** Starts the receive loop; datagrams queued in the socket buffer meanwhile are not lost. */
    void start(PacketHandler handler) {
        socket.start((data, length, from) -> datagram(handler, data, length, from));
    }

    /** @return the socket, for its bound port and address and its receive buffer size */
    DatagramLink socket() {
        return socket;
    }

    private void datagram(PacketHandler handler, byte[] data, int length, InetSocketAddress sender) {
        String from = "udp " + sender.getAddress().getHostAddress() + ":" + sender.getPort();
        SourceGate g = gate;
        SourceGate.Verdict verdict = g == null ? SourceGate.Verdict.PASS : g.check(sender.getAddress());
        if (verdict == SourceGate.Verdict.PASS) {
            handler.datagram(data, length, from);
            return;
        }
        String first = g.firstRefusal(verdict, sender.getAddress());
        if (first != null) {
            LOG.warn("UDP link {}: {}", socket.localAddress(), first);
            problems.accept(first);
        }
        handler.refused(SourceGate.why(verdict, sender.getAddress()), data, length, from);
    }

    @Override
    public void close() {
        socket.close();
    }
}

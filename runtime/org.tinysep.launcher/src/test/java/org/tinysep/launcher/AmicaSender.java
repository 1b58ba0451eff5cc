package org.tinysep.launcher;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;

/**
 * Real AmICA frames over UDP to a bus radio on 127.0.0.1, as nodes send them. Written once for the launcher's
 * process tests (ReadyIT, KillRestartIT, AlertKillRestartIT); the sequence number counts on across all nodes.
 */
final class AmicaSender implements AutoCloseable {

    private final InetSocketAddress radio;
    private final DatagramSocket socket;
    private int sequence;

    AmicaSender(int port) throws IOException {
        radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), port);
        socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
    }

    /** Sends the keep-alive of movement node {@code group.address}. */
    void keepAlive(int group, int address) throws IOException {
        send(group, address, new KeepAlive(120, 2900, 0x0A11,
                AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 4242));
    }

    /** Sends a motion report ("motion" or "no motion") of movement node {@code group.address}. */
    void motion(int group, int address, boolean detected) throws IOException {
        send(group, address, new MotionDetection(detected));
    }

    /** @return movement node {@code group.address} sending through this sender */
    Node node(int group, int address) {
        return new Node(group, address);
    }

    private void send(int group, int address, AmicaPayload payload) throws IOException {
        byte[] b = AmicaCodec.encode(new AmicaFrame(group, address, AmicaCodec.PLATFORM_ADDRESS, sequence++ & 0xFF,
                AmicaPayloads.encode(payload)));
        socket.send(new DatagramPacket(b, b.length, radio));
    }

    @Override
    public void close() {
        socket.close();
    }

    /** One movement node, so a test names its address once. */
    final class Node {
        private final int group;
        private final int address;

        private Node(int group, int address) {
            this.group = group;
            this.address = address;
        }

        void keepAlive() throws IOException {
            AmicaSender.this.keepAlive(group, address);
        }

        void motion(boolean detected) throws IOException {
            AmicaSender.this.motion(group, address, detected);
        }
    }
}

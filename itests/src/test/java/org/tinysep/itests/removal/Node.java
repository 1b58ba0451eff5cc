package org.tinysep.itests.removal;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.util.List;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;

/** A simulated AmICA node sending keep-alives from its own UDP socket on 127.0.0.1. */
final class Node implements AutoCloseable {

    private final int address;
    private final AmicaNodeType type;
    private final DatagramSocket socket;
    private int sequence;

    Node(int address, AmicaNodeType type) throws IOException {
        this.address = address;
        this.type = type;
        this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
    }

    /** @return the node address as devices show it, e.g. {@code 1.17} */
    String id() {
        return "1." + address;
    }

    void keepAlive(int radioPort) throws IOException {
        byte[] frame = AmicaCodec.encode(new AmicaFrame(1, address, 0, sequence++ & 0xFF, AmicaPayloads.encode(
                new KeepAlive(120, 2900, 0x0A11, AmicaNodeType.productId(List.of(type)), 4242))));
        socket.send(new DatagramPacket(frame, frame.length, InetAddress.getLoopbackAddress(), radioPort));
    }

    @Override
    public void close() {
        socket.close();
    }
}

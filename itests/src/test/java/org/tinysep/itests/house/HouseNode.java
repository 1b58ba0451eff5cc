package org.tinysep.itests.house;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;

/** A simulated AmICA movement node sending keep-alives over UDP on 127.0.0.1 (after org.tinysep.itests.AmicaNode). */
final class HouseNode implements AutoCloseable {

    private final int netgroup;
    private final int address;
    private final DatagramSocket socket;
    private final InetSocketAddress radio;
    private int sequence;

    HouseNode(int netgroup, int address, int radioPort) throws IOException {
        this.netgroup = netgroup;
        this.address = address;
        this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), radioPort);
    }

    void keepAlive() throws IOException {
        byte[] payload = AmicaPayloads.encode(new KeepAlive(120, 2900, 0x0A11,
                AmicaNodeType.productId(java.util.List.of(AmicaNodeType.MOVEMENT)), 4242));
        byte[] frame = AmicaCodec.encode(new AmicaFrame(netgroup, address, 0, sequence++ & 0xFF, payload));
        socket.send(new DatagramPacket(frame, frame.length, radio));
    }

    @Override
    public void close() {
        socket.close();
    }
}

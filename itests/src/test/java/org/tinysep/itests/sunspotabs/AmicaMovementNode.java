package org.tinysep.itests.sunspotabs;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;

/** A simulated AmICA movement node that only announces itself (keep-alive) to the UDP bus radio. */
final class AmicaMovementNode implements AutoCloseable {

    private final int netgroup;
    private final int address;
    private final DatagramSocket socket;
    private final InetSocketAddress radio;

    AmicaMovementNode(int netgroup, int address, int radioPort) throws IOException {
        this.netgroup = netgroup;
        this.address = address;
        this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), radioPort);
    }

    String id() {
        return netgroup + "." + address;
    }

    void keepAlive() throws IOException {
        KeepAlive k = new KeepAlive(120, 2900, 0x0A11, AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 4242);
        byte[] frame = AmicaCodec.encode(new AmicaFrame(netgroup, address, 0, 0, AmicaPayloads.encode(k)));
        socket.send(new DatagramPacket(frame, frame.length, radio));
    }

    @Override
    public void close() {
        socket.close();
    }
}

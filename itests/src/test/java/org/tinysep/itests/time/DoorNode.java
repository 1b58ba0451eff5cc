package org.tinysep.itests.time;

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
import org.tinysep.amica.protocol.ReedSwitchStatus;

/** A simulated AmICA door node (reed switch) sending real frames over UDP on 127.0.0.1 to the bus radio. */
final class DoorNode implements AutoCloseable {

    private final int netgroup;
    private final int address;
    private final DatagramSocket socket;
    private final InetSocketAddress radio;
    private int sequence;

    DoorNode(int netgroup, int address, int radioPort) throws IOException {
        this.netgroup = netgroup;
        this.address = address;
        this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), radioPort);
    }

    void keepAlive() throws IOException {
        send(new KeepAlive(120, 2900, 0x0A11, AmicaNodeType.productId(List.of(AmicaNodeType.DOOR)), 4242));
    }

    void door(boolean open) throws IOException {
        send(new ReedSwitchStatus(open));
    }

    private void send(AmicaPayload payload) throws IOException {
        byte[] b = AmicaCodec.encode(new AmicaFrame(netgroup, address, 0, sequence++ & 0xFF,
                AmicaPayloads.encode(payload)));
        socket.send(new DatagramPacket(b, b.length, radio));
    }

    @Override
    public void close() {
        socket.close();
    }
}

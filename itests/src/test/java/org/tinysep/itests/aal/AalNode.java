package org.tinysep.itests.aal;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.util.Arrays;
import java.util.List;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;

/**
 * A simulated AmICA node (a copy of the package-private {@code org.tinysep.itests.AmicaNode}): real frames from its
 * own UDP socket on 127.0.0.1 to the bus radio, and the frames the platform sends back to it.
 */
final class AalNode implements AutoCloseable {

    private final int netgroup;
    private final int address;
    private final List<AmicaNodeType> types;
    private final DatagramSocket socket;
    private final InetSocketAddress radio;
    private int sequence;

    AalNode(int netgroup, int address, int radioPort, AmicaNodeType... types) throws IOException {
        this.netgroup = netgroup;
        this.address = address;
        this.types = List.of(types);
        this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        this.socket.setSoTimeout(5000);
        this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), radioPort);
    }

    /** @return {@code netgroup.address}, the devices' {@code tinysep.node.address} */
    String id() {
        return netgroup + "." + address;
    }

    void keepAlive() throws IOException {
        send(new KeepAlive(120, 2900, 0x0A11, AmicaNodeType.productId(types), 4242));
    }

    void motion() throws IOException {
        send(new MotionDetection(true));
    }

    void send(AmicaPayload payload) throws IOException {
        byte[] b = AmicaCodec.encode(new AmicaFrame(netgroup, address, AmicaCodec.PLATFORM_ADDRESS,
                sequence++ & 0xFF, AmicaPayloads.encode(payload)));
        socket.send(new DatagramPacket(b, b.length, radio));
    }

    /** @return the payload of the next frame the platform sends to this node; fails after 5 s */
    byte[] receivePayload() throws Exception {
        DatagramPacket p = new DatagramPacket(new byte[512], 512);
        try {
            socket.receive(p);
        } catch (SocketTimeoutException e) {
            throw new AssertionError("node " + id() + " received no frame within 5 s");
        }
        return AmicaCodec.decode(Arrays.copyOf(p.getData(), p.getLength()), 0, p.getLength()).payload();
    }

    @Override
    public void close() {
        socket.close();
    }
}

package org.tinysep.itests;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.Arrays;
import java.util.List;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;

/**
 * A simulated AmICA node for integration tests: sends real frames from its own UDP socket on 127.0.0.1 to the
 * platform's bus radio, and can read what the platform sends back.
 */
public final class AmicaNode implements AutoCloseable {

    private final int netgroup;
    private final int address;
    private final List<AmicaNodeType> types;
    private final DatagramSocket socket;
    private final InetSocketAddress radio;
    private int sequence;

    public AmicaNode(int netgroup, int address, int radioPort, AmicaNodeType... types) throws IOException {
        this.netgroup = netgroup;
        this.address = address;
        this.types = List.of(types);
        this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        this.socket.setSoTimeout(5000);
        this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), radioPort);
    }

    public String id() {
        return netgroup + "." + address;
    }

    public void keepAlive() throws IOException {
        send(new KeepAlive(120, 2900, 0x0A11, AmicaNodeType.productId(types), 4242));
    }

    public void motion(boolean detected) throws IOException {
        send(new MotionDetection(detected));
    }

    public void door(boolean open) throws IOException {
        send(new ReedSwitchStatus(open));
    }

    public void send(AmicaPayload payload) throws IOException {
        raw(AmicaCodec.encode(new AmicaFrame(netgroup, address, 0, sequence++ & 0xFF, AmicaPayloads.encode(payload))));
    }

    /** Sends any bytes as one datagram, e.g. garbage. */
    public void raw(byte[] datagram) throws IOException {
        socket.send(new DatagramPacket(datagram, datagram.length, radio));
    }

    /** @return the payload of the next frame the platform sends to this node (5 s timeout) */
    public byte[] receivePayload() throws Exception {
        DatagramPacket p = new DatagramPacket(new byte[512], 512);
        socket.receive(p);
        return AmicaCodec.decode(Arrays.copyOf(p.getData(), p.getLength()), 0, p.getLength()).payload();
    }

    @Override
    public void close() {
        socket.close();
    }
}

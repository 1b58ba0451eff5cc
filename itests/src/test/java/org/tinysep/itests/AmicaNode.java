package org.tinysep.itests;

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
import org.tinysep.amica.protocol.ReedSwitchStatus;

/**
 * A simulated AmICA node for integration tests: sends real frames from its own UDP socket on 127.0.0.1 to the
 * platform's bus radio, and reads the frames the platform sends back to it, checking they are addressed to it.
 * (The simulator module's nodes play whole flats; this one is driven step by step by a test.)
 */
public final class AmicaNode implements AutoCloseable {

    /** How long {@link #receivePayload()} waits for a command from the platform. */
    public static final int RECEIVE_TIMEOUT_MS = 5000;

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
        this.socket.setSoTimeout(RECEIVE_TIMEOUT_MS);
        this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), radioPort);
    }

    /** @return {@code netgroup.address}, the devices' {@code tinysep.node.address} */
    public String id() {
        return netgroup + "." + address;
    }

    /** Sends a keep-alive whose product id has exactly this node's type bits. */
    public void keepAlive() throws IOException {
        send(new KeepAlive(120, 2900, 0x0A11, AmicaNodeType.productId(types), 4242));
    }

    public void motion(boolean detected) throws IOException {
        send(new MotionDetection(detected));
    }

    public void door(boolean open) throws IOException {
        send(new ReedSwitchStatus(open));
    }

    /** Sends one payload (thesis Table 3.1) from this node to the platform. */
    public void send(AmicaPayload payload) throws IOException {
        raw(AmicaCodec.encode(new AmicaFrame(netgroup, address, AmicaCodec.PLATFORM_ADDRESS, sequence++ & 0xFF, AmicaPayloads.encode(payload))));
    }

    /** Sends any bytes as one datagram, e.g. garbage. */
    public void raw(byte[] datagram) throws IOException {
        socket.send(new DatagramPacket(datagram, datagram.length, radio));
    }

    /**
     * @return the payload of the next frame the platform sends to this node
     * @throws AssertionError if none arrives within {@value #RECEIVE_TIMEOUT_MS} ms, or it is not addressed here
     */
    public byte[] receivePayload() throws Exception {
        DatagramPacket p = new DatagramPacket(new byte[512], 512);
        try {
            socket.receive(p);
        } catch (SocketTimeoutException e) {
            throw new AssertionError("node " + id() + " received no frame within " + RECEIVE_TIMEOUT_MS + " ms");
        }
        AmicaFrame frame = AmicaCodec.decode(Arrays.copyOf(p.getData(), p.getLength()), 0, p.getLength());
        if (frame.netgroup() != netgroup || frame.destination() != address
                || frame.source() != AmicaCodec.PLATFORM_ADDRESS) {
            throw new AssertionError("frame for " + frame.netgroup() + "." + frame.destination() + " from "
                    + frame.source() + " reached node " + id());
        }
        return frame.payload();
    }

    @Override
    public void close() {
        socket.close();
    }
}

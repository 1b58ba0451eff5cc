package org.tinysep.itests.sunspotabs;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/**
 * A simulated Sun SPOT node for integration tests: sends real frames (one per UDP datagram, encoded by the shared
 * protocol library) from its own socket on 127.0.0.1 to the platform's Sun SPOT bus radio.
 */
final class SunSpotNode implements AutoCloseable {

    private final SunSpotAddress address;
    private final DatagramSocket socket;
    private final InetSocketAddress radio;

    SunSpotNode(String address, int radioPort) throws IOException {
        this.address = SunSpotAddress.parse(address);
        this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), radioPort);
    }

    /** @return the address as the platform shows it, e.g. {@code 0014.4F01.0000.1234} */
    String address() {
        return address.toString();
    }

    /** @return an LDAP filter matching this node's services */
    String filter() {
        return "(tinysep.node.address=" + address + ")";
    }

    /** Sends payloads in order, each in a frame whose header sensor type is the payload's own. */
    void send(SunSpotPayload... payloads) throws IOException {
        for (SunSpotPayload payload : payloads) {
            byte[] frame = SunSpotCodec.encode(
                    new SunSpotFrame(address, payload.sensorType().code(), SunSpotPayloads.encode(payload)));
            socket.send(new DatagramPacket(frame, frame.length, radio));
        }
    }

    @Override
    public void close() {
        socket.close();
    }
}

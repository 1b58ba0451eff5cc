package org.tinysep.itests.sunspot;

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
 * Sends real Sun SPOT frames, one per UDP datagram, from its own socket on 127.0.0.1 to the bus radio's UDP link,
 * as a simulator or a forwarding program next to a basestation would.
 */
final class SunSpotSender implements AutoCloseable {

    private final DatagramSocket socket;
    private final InetSocketAddress radio;

    SunSpotSender(int radioPort) throws IOException {
        this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), radioPort);
    }

    /** Sends one payload from {@code source} in a frame whose header sensor type is the payload's first byte. */
    void send(String source, SunSpotPayload payload) throws IOException {
        raw(SunSpotCodec.encode(SunSpotFrame.of(SunSpotAddress.parse(source), SunSpotPayloads.encode(payload))));
    }

    /** Sends any bytes as one datagram. */
    void raw(byte[] datagram) throws IOException {
        socket.send(new DatagramPacket(datagram, datagram.length, radio));
    }

    @Override
    public void close() {
        socket.close();
    }
}

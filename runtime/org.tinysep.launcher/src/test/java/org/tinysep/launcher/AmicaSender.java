package org.tinysep.launcher;

import java.io.IOException;
import java.io.UncheckedIOException;
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

/** Real AmICA frames over UDP to a bus radio on 127.0.0.1, as nodes send them. */
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
        byte[] b = AmicaCodec.encode(new AmicaFrame(group, address, AmicaCodec.PLATFORM_ADDRESS, sequence++ & 0xFF,
                AmicaPayloads.encode(new KeepAlive(120, 2900, 0x0A11,
                        AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 4242))));
        socket.send(new DatagramPacket(b, b.length, radio));
    }

    static int freeUdpPort() {
        try (DatagramSocket s = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void close() {
        socket.close();
    }
}

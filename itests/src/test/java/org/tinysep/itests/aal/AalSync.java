package org.tinysep.itests.aal;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.time.Instant;

/**
 * A minimal lock-step time synchroniser (a copy of {@code org.tinysep.itests.time.SyncPeer}): each TICK waits for
 * the platform's DONE, after which every listener of that second has run.
 */
final class AalSync implements AutoCloseable {

    private final DatagramSocket socket;
    private final InetSocketAddress platform;
    private final byte[] buffer = new byte[512];
    private long seq;

    AalSync(int platformPort) throws IOException {
        socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        socket.setSoTimeout(5000);
        platform = new InetSocketAddress(InetAddress.getLoopbackAddress(), platformPort);
    }

    /** Sends {@code TICK <seq> <at>} and checks the answer is {@code DONE <seq> <at>}. */
    void tickDone(Instant at) throws IOException {
        byte[] b = ("TICK " + (++seq) + " " + at).getBytes(StandardCharsets.US_ASCII);
        socket.send(new DatagramPacket(b, b.length, platform));
        DatagramPacket in = new DatagramPacket(buffer, buffer.length);
        socket.receive(in);
        String answer = new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII);
        String expected = "DONE " + seq + " " + at;
        if (!expected.equals(answer)) {
            throw new AssertionError("expected '" + expected + "' but the platform answered '" + answer + "'");
        }
    }

    @Override
    public void close() {
        socket.close();
    }
}

package org.tinysep.itests.aal;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import org.tinysep.itests.TestSyncKey;

/**
 * A minimal lock-step time synchroniser (a copy of {@code org.tinysep.itests.time.SyncPeer}): each TICK waits for
 * the platform's DONE, after which every listener of that second has run. Signed with the tests' key
 * ({@link TestSyncKey}) for the session of its first HELLO.
 */
final class AalSync implements AutoCloseable {

    private final DatagramSocket socket;
    private final InetSocketAddress platform;
    private final byte[] buffer = new byte[512];
    private long seq;
    private final String session;

    AalSync(int platformPort) throws IOException {
        socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        socket.setSoTimeout(5000);
        platform = new InetSocketAddress(InetAddress.getLoopbackAddress(), platformPort);
        String[] welcome = ask("HELLO").split(" ");
        if (welcome.length != 4 || !welcome[0].equals("WELCOME")) {
            throw new AssertionError("expected WELCOME <instant> <mode> <session>, got " + String.join(" ", welcome));
        }
        session = welcome[3];
    }

    private String ask(String request) throws IOException {
        byte[] b = request.getBytes(StandardCharsets.US_ASCII);
        socket.send(new DatagramPacket(b, b.length, platform));
        DatagramPacket in = new DatagramPacket(buffer, buffer.length);
        socket.receive(in);
        return new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII);
    }

    /** Sends {@code TICK <seq> <at> <hmac>} and checks the answer is {@code DONE <seq> <at>}. */
    void tickDone(Instant at) throws IOException {
        String answer = ask(TestSyncKey.signed(session, "TICK " + (++seq) + " " + at));
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

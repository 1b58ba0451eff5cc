package org.tinysep.itests;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.time.Instant;

/**
 * The integration tests' time synchroniser (docs/time-sync.md) on its own UDP socket of 127.0.0.1: sends one
 * request and waits for the answer (5 s at most unless told), i.e. lock-step. TICKs are signed with the tests' key
 * ({@link TestSyncKey}) for the session of the last WELCOME (a HELLO is sent first when there was none). The one
 * test client of the Time Controller's synchroniser link, for the time, AAL and health tests alike.
 */
public final class SyncPeer implements AutoCloseable {

    private final DatagramSocket socket;
    private final InetSocketAddress platform;
    private final byte[] buffer = new byte[512];
    private long seq;
    private String session;

    /** A synchroniser of the platform's port {@code platformPort} ({@link TinySepTestSupport#syncPort()}). */
    public SyncPeer(int platformPort) throws IOException {
        this(platformPort, 5000);
    }

    /** @param timeoutMillis how long each request waits for its answer */
    public SyncPeer(int platformPort, int timeoutMillis) throws IOException {
        socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        socket.setSoTimeout(timeoutMillis);
        platform = new InetSocketAddress(InetAddress.getLoopbackAddress(), platformPort);
    }

    /**
     * Sends HELLO now (rather than before the first TICK) and checks the answer is
     * {@code WELCOME <instant> <mode> <session>}.
     *
     * @return this
     */
    public SyncPeer hello() throws IOException {
        String answer = ask("HELLO");
        String[] welcome = answer.split(" ");
        if (welcome.length != 4 || !welcome[0].equals("WELCOME")) {
            throw new AssertionError("expected WELCOME <instant> <mode> <session>, got " + answer);
        }
        return this;
    }

    /** Sends one datagram as it is and returns the answer; a WELCOME's session is kept for signing. */
    public String ask(String request) throws IOException {
        byte[] b = request.getBytes(StandardCharsets.US_ASCII);
        socket.send(new DatagramPacket(b, b.length, platform));
        DatagramPacket in = new DatagramPacket(buffer, buffer.length);
        socket.receive(in);
        String answer = new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII);
        String[] w = answer.split(" ");
        if (w[0].equals("WELCOME") && w.length == 4) {
            session = w[3];
        }
        return answer;
    }

    /** Sends {@code request} signed with the tests' key; returns the answer. */
    public String askSigned(String request) throws IOException {
        if (session == null) {
            ask("HELLO");
        }
        return ask(TestSyncKey.signed(session, request));
    }

    /** {@code TICK <next seq> <at> <hmac>}; returns the answer ({@code DONE ...} or {@code ERROR ...}). */
    public String tick(Instant at) throws IOException {
        return askSigned("TICK " + (++seq) + " " + at);
    }

    /** Sends {@code TICK <next seq> <at>} and checks the answer is {@code DONE <seq> <at>}. */
    public void tickDone(Instant at) throws IOException {
        String answer = tick(at);
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

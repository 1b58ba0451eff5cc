package org.tinysep.simulator.time;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.time.Instant;

/**
 * The synchroniser side of docs/time-sync.md: {@code HELLO} -> {@code WELCOME}, {@code TICK <seq> <instant>} ->
 * {@code DONE <seq> <instant>}. A lost answer is retried with the same sequence number and instant (the platform
 * answers a retransmission without firing again).
 */
public final class SyncClient implements AutoCloseable {

    public static final int DEFAULT_PORT = 47020;
    private static final int TRIES = 3;

    private final DatagramSocket socket;
    private final InetSocketAddress platform;
    private final byte[] buffer = new byte[512];
    private long seq;

    public SyncClient(InetSocketAddress platform, int timeoutMillis) throws IOException {
        this.platform = platform;
        this.socket = new DatagramSocket(platform.getAddress().isLoopbackAddress()
                ? new InetSocketAddress(platform.getAddress(), 0) : new InetSocketAddress(0));
        socket.setSoTimeout(timeoutMillis);
    }

    public Welcome hello() throws IOException {
        String answer = ask("HELLO", "WELCOME ");
        String[] w = answer.split(" ");
        if (w.length != 3) {
            throw new IOException("unexpected answer to HELLO: '" + answer + "'");
        }
        return new Welcome(Instant.parse(w[1]), w[2]);
    }

    /** Sends one TICK and returns when the platform answered DONE; throws with the platform's ERROR text. */
    public void tick(Instant at) throws IOException {
        seq++;
        ask("TICK " + seq + " " + at, "DONE " + seq + " ");
    }

    private String ask(String request, String expected) throws IOException {
        byte[] b = request.getBytes(StandardCharsets.US_ASCII);
        for (int attempt = 1; attempt <= TRIES; attempt++) {
            socket.send(new DatagramPacket(b, b.length, platform));
            try {
                while (true) {
                    DatagramPacket in = new DatagramPacket(buffer, buffer.length);
                    socket.receive(in);
                    String answer = new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII);
                    if (answer.startsWith(expected)) {
                        return answer;
                    }
                    if (answer.startsWith("ERROR " + seq + " ") || answer.startsWith("ERROR - ")) {
                        throw new IOException("the platform refused '" + request + "': " + answer);
                    }
                    // a late answer to an earlier request: skip it
                }
            } catch (SocketTimeoutException e) {
                // retry
            }
        }
        throw new IOException("no answer to '" + request + "' from the Time Controller at " + platform + " after "
                + TRIES + " tries (is the platform running, with its time synchroniser on this port?)");
    }

    @Override
    public void close() {
        socket.close();
    }
}

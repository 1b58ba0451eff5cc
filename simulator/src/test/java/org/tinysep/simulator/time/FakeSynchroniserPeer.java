package org.tinysep.simulator.time;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

/**
 * The platform's side of docs/time-sync.md, reduced to what the simulator needs: WELCOME, DONE at once, ERROR
 * backwards, and (optionally) the first TICK's answer lost.
 */
public final class FakeSynchroniserPeer implements AutoCloseable {

    /** The session value this fake announces in WELCOME (the real platform's is random). */
    public static final String SESSION = "5e55105e55105e55";
    private final DatagramSocket socket;
    private final ExecutorService executor = Executors.newSingleThreadExecutor();
    private final String mode;
    private volatile boolean loseFirstDone;
    private volatile Instant now = Instant.parse("2026-11-22T12:00:00Z");
    public final List<String> requests = Collections.synchronizedList(new ArrayList<>());
    public final List<Instant> ticks = new ArrayList<>();

    public FakeSynchroniserPeer(String mode) throws IOException {
        this.mode = mode;
        socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        executor.execute(this::serve);
    }

    public InetSocketAddress address() {
        return new InetSocketAddress(InetAddress.getLoopbackAddress(), socket.getLocalPort());
    }

    public void loseFirstDone() {
        loseFirstDone = true;
    }

    private volatile long lastAccepted;

    /** As the Time Controller for a sender whose address (IP and port) already sent up to {@code seq} in its session. */
    public void lastAccepted(long seq) {
        lastAccepted = seq;
    }

    private void serve() {
        byte[] buf = new byte[512];
        String last = null;
        while (!socket.isClosed()) {
            DatagramPacket p = new DatagramPacket(buf, buf.length);
            try {
                socket.receive(p);
                String req = new String(p.getData(), 0, p.getLength(), StandardCharsets.US_ASCII);
                requests.add(req);
                String[] w = req.split(" ");
                String answer;
                if (w[0].equals("BYE")) {
                    answer = "DONE " + w[1] + " " + now;
                } else if (w[0].equals("HELLO")) {
                    answer = "WELCOME " + now + " " + mode + " " + SESSION;
                } else if (!w[0].equals("HELLO") && w.length > 1 && Long.parseLong(w[1]) <= lastAccepted) {
                    answer = "ERROR " + w[1] + " replayed sequence number " + w[1] + " is not above the last accepted "
                            + lastAccepted + " of this session";
                } else if (req.equals(last)) {
                    answer = "DONE " + w[1] + " " + w[2];
                } else if (Instant.parse(w[2]).isBefore(now)) {
                    answer = "ERROR " + w[1] + " backwards " + w[2] + " is before the current time " + now;
                } else {
                    now = Instant.parse(w[2]);
                    synchronized (ticks) {
                        ticks.add(now);
                    }
                    last = req;
                    answer = "DONE " + w[1] + " " + now;
                    if (loseFirstDone) {
                        loseFirstDone = false;
                        continue;
                    }
                }
                byte[] b = answer.getBytes(StandardCharsets.US_ASCII);
                socket.send(new DatagramPacket(b, b.length, p.getSocketAddress()));
            } catch (SocketException closed) {
                return;
            } catch (IOException e) {
                // keep serving
            }
        }
    }

    public List<Instant> ticks() {
        synchronized (ticks) {
            return List.copyOf(ticks);
        }
    }

    @Override
    public void close() throws InterruptedException {
        socket.close();
        executor.shutdownNow();
        executor.awaitTermination(5, TimeUnit.SECONDS);
    }
}

package org.tinysep.simulator.time;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Instant;
import org.tinysep.link.sync.SyncSecret;

/**
 * The synchroniser side of docs/time-sync.md: {@code HELLO} -> {@code WELCOME <instant> <mode> <session>},
 * {@code TICK <seq> <instant> <hmac>} -> {@code DONE <seq> <instant>}, {@code BYE <seq> <hmac>} -> {@code DONE}. The
 * HMAC-SHA256 (hex) of {@code "<session> TICK <seq> <instant>"} is made with the platform's key file
 * ({@code --sync-key}). A lost answer is retried with the same sequence number and instant (the platform answers a
 * retransmission without firing again).
 */
public final class SyncClient implements AutoCloseable {

    public static final int DEFAULT_PORT = 47020;
    private static final int TRIES = 3;

    private final DatagramSocket socket;
    private final InetSocketAddress platform;
    private final byte[] buffer = new byte[512];
    private final byte[] key;
    private String session = "";
    private long seq;

    /** A client without the key: the platform refuses its TICKs (only fakes in tests accept them). */
    public SyncClient(InetSocketAddress platform, int timeoutMillis) throws IOException {
        this(platform, timeoutMillis, null);
    }

    /** @param key the platform's synchroniser key ({@link #readKey}), or null */
    public SyncClient(InetSocketAddress platform, int timeoutMillis, byte[] key) throws IOException {
        this.platform = platform;
        this.key = key == null ? null : key.clone();
        this.socket = new DatagramSocket(platform.getAddress().isLoopbackAddress()
                ? new InetSocketAddress(platform.getAddress(), 0) : new InetSocketAddress(0));
        socket.setSoTimeout(timeoutMillis);
    }

    /**
     * {@link #hello()}, asked again for up to {@code waitSeconds} while the platform does not answer or its clock is
     * still REAL (a platform that is starting and has not yet read its configuration).
     */
    public Welcome hello(int waitSeconds) throws IOException {
        long deadline = System.nanoTime() + waitSeconds * 1_000_000_000L;
        while (true) {
            try {
                Welcome w = hello();
                if (w.external() || System.nanoTime() >= deadline) {
                    return w;
                }
                java.util.concurrent.locks.LockSupport.parkNanos(500_000_000L);
            } catch (NoAnswer e) {
                if (System.nanoTime() >= deadline) {
                    throw e;
                }
            }
        }
    }

    /** No answer after every try (public: a harness may start the platform again, e.g. when its port was taken). */
    public static final class NoAnswer extends IOException {
        private static final long serialVersionUID = 1L;

        NoAnswer(String message) {
            super(message);
        }
    }

    public Welcome hello() throws IOException {
        String answer = ask("HELLO", "WELCOME ");
        String[] w = answer.split(" ");
        if (w.length != 3 && w.length != 4) {
            throw new IOException("unexpected answer to HELLO: '" + answer + "'");
        }
        session = w.length == 4 ? w[3] : "";
        return new Welcome(Instant.parse(w[1]), w[2]);
    }

    /** Sends one TICK and returns when the platform answered DONE; throws with the platform's ERROR text. */
    public void tick(Instant at) throws IOException {
        send(() -> "TICK " + seq + " " + at);
    }

    /** Tells the platform the synchronisation has finished: its clock returns to REAL time. */
    public void bye() throws IOException {
        send(() -> "BYE " + seq);
    }

    /**
     * Sends the next request. The platform keeps one session per sender address; a new run whose socket got the port
     * of an earlier run (the kernel reuses ephemeral ports) inherits that session and its sequence numbers
     * ({@code ERROR <seq> replayed ... not above the last accepted <n> ...}): then numbering continues at n + 1, once.
     */
    private void send(java.util.function.Supplier<String> request) throws IOException {
        seq++;
        try {
            ask(signed(request.get()), "DONE " + seq + " ");
        } catch (Replayed r) {
            seq = r.lastAccepted + 1;
            ask(signed(request.get()), "DONE " + seq + " ");
        }
    }

    /** The platform refused a sequence number as replayed; it said which one it accepted last. */
    static final class Replayed extends IOException {
        private static final long serialVersionUID = 1L;
        final long lastAccepted;

        Replayed(String message, long lastAccepted) {
            super(message);
            this.lastAccepted = lastAccepted;
        }
    }

    private static final java.util.regex.Pattern LAST_ACCEPTED =
            java.util.regex.Pattern.compile(" replayed .* not above the last accepted (\\d+)");

    /** The key as the platform reads it ({@link SyncSecret#read}). */
    public static byte[] readKey(Path file) throws IOException {
        return SyncSecret.read(file);
    }

    private String signed(String request) {
        if (key == null) {
            return request;
        }
        return request + " " + SyncSecret.hmac(key, session, request);
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
                    java.util.regex.Matcher replayed = LAST_ACCEPTED.matcher(answer);
                    if (answer.startsWith("ERROR " + seq + " replayed ") && replayed.find()) {
                        throw new Replayed(answer, Long.parseLong(replayed.group(1)));
                    }
                    if (answer.startsWith("ERROR " + seq + " ") || answer.startsWith("ERROR - ")) {
                        throw new IOException("the platform refused '" + request + "': " + answer
                                + (answer.contains(" unauthorized ") ? " (give --sync-key <the platform's state "
                                + "folder>/sync.key, shown by tinysep:time)" : ""));
                    }
                    // a late answer to an earlier request: skip it
                }
            } catch (SocketTimeoutException e) {
                // retry
            }
        }
        throw new NoAnswer("no answer to '" + request + "' from the Time Controller at " + platform + " after "
                + TRIES + " tries (is the platform running, with its time synchroniser on this port?)");
    }

    @Override
    public void close() {
        socket.close();
    }
}

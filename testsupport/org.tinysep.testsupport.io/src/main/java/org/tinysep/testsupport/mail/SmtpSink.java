package org.tinysep.testsupport.mail;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.SSLContext;

/**
 * The one SMTP server of the tests and the evaluation: small but real, on 127.0.0.1 (a free port on the first
 * {@link #start()}, the same port on every later one). It speaks plain SMTP (EHLO/HELO, MAIL FROM, RCPT TO, DATA
 * with dot-unstuffing, RSET, NOOP, QUIT) and records each accepted message. What a test may make it do:
 * <ul>
 * <li>{@link #stop()} closes the port and every open connection, so a client sees the server go down;
 * {@link #start()} brings it back on the same port;</li>
 * <li>{@link #mailboxFull} answers {@code 552 5.2.2 mailbox full} to RCPT for an address (RFC 5321 4.5.3.1.10: the
 * client must treat it as temporary); {@link #refuse} answers {@code 550 5.1.1 no such user} (permanent);</li>
 * <li>{@link #requireLogin} offers {@code AUTH PLAIN LOGIN} and refuses MAIL until that user logged in
 * ({@code 535} for wrong credentials, {@code 530} without a login);</li>
 * <li>{@link #tls} speaks TLS with a given server key: from the first byte ({@code smtps}) or after
 * {@code STARTTLS}, which is then required before MAIL.</li>
 * </ul>
 * Use it with the Mail Manager configured to {@code host=127.0.0.1}, {@code port=}{@link #port()} and the matching
 * {@code security} ({@code NONE} unless {@link #tls} was called).
 */
public final class SmtpSink implements AutoCloseable {

    /**
     * One accepted message: envelope sender, envelope recipients, the raw data (headers and body) and whether it
     * travelled inside TLS.
     */
    public record Received(String from, List<String> to, String data, boolean tls) {

        /** @return the value of the {@code Subject:} header, or "" */
        public String subject() {
            return header("Subject");
        }

        /** @return the (unfolded) value of the first header with this name, or "" */
        public String header(String name) {
            String[] lines = data.split("\r\n");
            for (int i = 0; i < lines.length && !lines[i].isEmpty(); i++) {
                String line = lines[i];
                if (line.length() > name.length() && line.charAt(name.length()) == ':'
                        && line.regionMatches(true, 0, name, 0, name.length())) {
                    StringBuilder value = new StringBuilder(line.substring(name.length() + 1).strip());
                    while (i + 1 < lines.length && !lines[i + 1].isEmpty()
                            && (lines[i + 1].charAt(0) == ' ' || lines[i + 1].charAt(0) == '\t')) {
                        value.append(' ').append(lines[++i].strip());
                    }
                    return value.toString();
                }
            }
            return "";
        }

        /** @return the text after the header block, lines joined with CRLF */
        public String body() {
            int i = data.indexOf("\r\n\r\n");
            return i < 0 ? "" : data.substring(i + 4);
        }
    }

    /** A user name and password the server accepts. */
    record Login(String user, String password) {
    }

    final List<Received> received = new CopyOnWriteArrayList<>();
    final List<String> handshakeFailures = new CopyOnWriteArrayList<>();
    private final Set<Socket> clients = ConcurrentHashMap.newKeySet();
    private final Set<String> fullMailboxes = ConcurrentHashMap.newKeySet();
    private final Set<String> refused = ConcurrentHashMap.newKeySet();
    private volatile Login login;
    private volatile SSLContext tls;
    private volatile boolean implicitTls;
    private volatile ServerSocket server;
    private volatile ExecutorService threads;
    private int port;

    /**
     * Makes the server speak TLS with the key of {@code context} (call before {@link #start()}).
     *
     * @param implicit true: TLS from the first byte ({@code smtps}); false: plain, {@code STARTTLS} offered and
     *                 required before MAIL
     */
    public synchronized SmtpSink tls(SSLContext context, boolean implicit) {
        this.tls = context;
        this.implicitTls = implicit;
        return this;
    }

    /** Offers {@code AUTH PLAIN LOGIN} and accepts MAIL only after this user logged in with this password. */
    public SmtpSink requireLogin(String user, String password) {
        this.login = new Login(user, password);
        return this;
    }

    /** Opens the port (a free one the first time, the same one afterwards) and starts accepting. */
    public synchronized SmtpSink start() throws IOException {
        if (server != null) {
            return this;
        }
        ServerSocket s = tls != null && implicitTls ? tls.getServerSocketFactory().createServerSocket()
                : new ServerSocket();
        s.setReuseAddress(true);
        s.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
        port = s.getLocalPort();
        server = s;
        threads = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r, "smtp-sink-" + port);
            t.setDaemon(true);
            return t;
        });
        threads.execute(() -> acceptLoop(s));
        return this;
    }

    /** Closes the port and every open connection; recorded messages stay. */
    public synchronized void stop() {
        ServerSocket s = server;
        server = null;
        if (s == null) {
            return;
        }
        closeQuietly(s);
        clients.forEach(SmtpSink::closeQuietly);
        threads.shutdownNow();
        try {
            threads.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Makes RCPT for {@code address} answer {@code 552 5.2.2 mailbox full} (or, with false, accept it again). */
    public void mailboxFull(String address, boolean full) {
        if (full) {
            fullMailboxes.add(address.toLowerCase(Locale.ROOT));
        } else {
            fullMailboxes.remove(address.toLowerCase(Locale.ROOT));
        }
    }

    /** Makes RCPT for {@code address} answer {@code 550 5.1.1 no such user}, for good. */
    public void refuse(String address) {
        refused.add(address.toLowerCase(Locale.ROOT));
    }

    /** @return the port, fixed by the first {@link #start()} */
    public synchronized int port() {
        return port;
    }

    /** @return the messages accepted so far, in order */
    public List<Received> messages() {
        return List.copyOf(received);
    }

    /** @return the envelope recipients of the messages accepted so far, once per message, in order */
    public List<String> recipients() {
        return received.stream().flatMap(m -> m.to().stream()).toList();
    }

    /** @return why each failed TLS handshake failed (e.g. the client refused the certificate) */
    public List<String> handshakeFailures() {
        return List.copyOf(handshakeFailures);
    }

    /** Waits until at least {@code count} messages were accepted. @return whether they were, within the limit */
    public boolean await(int count, Duration timeout) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (received.size() < count) {
            if (System.nanoTime() > deadline) {
                return false;
            }
            Thread.sleep(20);
        }
        return true;
    }

    @Override
    public void close() {
        stop();
    }

    /** @return the RCPT reply for this address: a refusal, or null to accept it */
    String refusal(String address) {
        String a = address.toLowerCase(Locale.ROOT);
        if (refused.contains(a)) {
            return "550 5.1.1 no such user";
        }
        return fullMailboxes.contains(a) ? "552 5.2.2 mailbox full" : null;
    }

    Login login() {
        return login;
    }

    /** @return the TLS context for STARTTLS, or null when the server offers none (plain, or TLS from the start) */
    SSLContext startTls() {
        return implicitTls ? null : tls;
    }

    private void acceptLoop(ServerSocket s) {
        while (!s.isClosed()) {
            try {
                Socket c = s.accept();
                clients.add(c);
                threads.execute(() -> {
                    try {
                        new SmtpDialogue(this, c).run();
                    } finally {
                        clients.remove(c);
                    }
                });
            } catch (IOException | RejectedExecutionException e) {
                return; // stopped
            }
        }
    }

    static void closeQuietly(java.io.Closeable c) {
        try {
            c.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }
}

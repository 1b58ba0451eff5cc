package org.tinysep.testsupport.mail;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

/**
 * A small but real SMTP server for integration tests: listens on 127.0.0.1 (a free port on the first
 * {@link #start()}, the same port on every later one), speaks plain SMTP (EHLO/HELO, MAIL FROM, RCPT TO, DATA
 * with dot-unstuffing, RSET, NOOP, QUIT; no AUTH, no STARTTLS) and records each accepted message. {@link #stop()}
 * closes the port and every open connection, so a client sees the server go down; {@link #start()} brings it
 * back. {@link #mailboxFull} makes it answer {@code 552 5.2.2 mailbox full} to RCPT for an address (RFC 5321
 * 4.5.3.1.10: the client must treat it as temporary). Use it with the Mail Manager configured to
 * {@code security=NONE}, {@code host=127.0.0.1}, {@code port=}{@link #port()}.
 */
public final class SmtpSink implements AutoCloseable {

    /** One accepted message: envelope sender, envelope recipients and the raw data (headers and body). */
    public record Received(String from, List<String> to, String data) {

        /** @return the value of the {@code Subject:} header, or "" */
        public String subject() {
            for (String line : data.split("\r\n")) {
                if (line.isEmpty()) {
                    break;
                }
                if (line.regionMatches(true, 0, "Subject:", 0, 8)) {
                    return line.substring(8).strip();
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

    private final List<Received> received = new CopyOnWriteArrayList<>();
    private final Set<Socket> clients = ConcurrentHashMap.newKeySet();
    private final Set<String> fullMailboxes = ConcurrentHashMap.newKeySet();
    private volatile ServerSocket server;
    private volatile ExecutorService threads;
    private int port;

    /** Opens the port (a free one the first time, the same one afterwards) and starts accepting. */
    public synchronized SmtpSink start() throws IOException {
        if (server != null) {
            return this;
        }
        ServerSocket s = new ServerSocket();
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

    /** @return the port, fixed by the first {@link #start()} */
    public synchronized int port() {
        return port;
    }

    /** @return the messages accepted so far, in order */
    public List<Received> messages() {
        return List.copyOf(received);
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

    private void acceptLoop(ServerSocket s) {
        while (!s.isClosed()) {
            try {
                Socket c = s.accept();
                clients.add(c);
                threads.execute(() -> session(c));
            } catch (IOException | java.util.concurrent.RejectedExecutionException e) {
                return; // stopped
            }
        }
    }

    private void session(Socket c) {
        try (c) {
            c.setSoTimeout(10_000);
            BufferedReader in = new BufferedReader(new InputStreamReader(c.getInputStream(), StandardCharsets.UTF_8));
            OutputStream out = c.getOutputStream();
            reply(out, "220 smtp-sink ESMTP ready");
            String from = null;
            List<String> to = new ArrayList<>();
            String line;
            while ((line = in.readLine()) != null) {
                String verb = line.length() < 4 ? line.toUpperCase(Locale.ROOT) : line.substring(0, 4).toUpperCase(Locale.ROOT);
                switch (verb) {
                    case "EHLO" -> reply(out, "250-smtp-sink\r\n250-8BITMIME\r\n250 SMTPUTF8");
                    case "HELO" -> reply(out, "250 smtp-sink");
                    case "MAIL" -> {
                        from = address(line);
                        to.clear();
                        reply(out, "250 sender ok");
                    }
                    case "RCPT" -> {
                        if (fullMailboxes.contains(address(line).toLowerCase(Locale.ROOT))) {
                            reply(out, "552 5.2.2 mailbox full");
                            continue;
                        }
                        to.add(address(line));
                        reply(out, "250 recipient ok");
                    }
                    case "DATA" -> {
                        if (from == null || to.isEmpty()) {
                            reply(out, "503 need MAIL FROM and RCPT TO first");
                            continue;
                        }
                        reply(out, "354 end with <CRLF>.<CRLF>");
                        String data = readData(in);
                        if (data == null) {
                            return;
                        }
                        received.add(new Received(from, List.copyOf(to), data));
                        from = null;
                        to.clear();
                        reply(out, "250 message accepted");
                    }
                    case "RSET" -> {
                        from = null;
                        to.clear();
                        reply(out, "250 reset");
                    }
                    case "NOOP" -> reply(out, "250 ok");
                    case "QUIT" -> {
                        reply(out, "221 bye");
                        return;
                    }
                    default -> reply(out, "502 command not implemented");
                }
            }
        } catch (SocketException e) {
            // closed by stop() or by the client
        } catch (IOException e) {
            // a broken session ends; the server goes on
        } finally {
            clients.remove(c);
        }
    }

    /** Reads DATA lines up to the lone dot, undoing dot-stuffing. @return null if the connection ended first */
    private static String readData(BufferedReader in) throws IOException {
        StringBuilder b = new StringBuilder();
        String line;
        while ((line = in.readLine()) != null) {
            if (line.equals(".")) {
                return b.toString();
            }
            b.append(line.startsWith("..") ? line.substring(1) : line).append("\r\n");
        }
        return null;
    }

    private static String address(String line) {
        int lt = line.indexOf('<');
        int gt = line.indexOf('>', lt + 1);
        if (lt >= 0 && gt > lt) {
            return line.substring(lt + 1, gt);
        }
        int colon = line.indexOf(':');
        return colon < 0 ? "" : line.substring(colon + 1).strip();
    }

    private static void reply(OutputStream out, String text) throws IOException {
        out.write((text + "\r\n").getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    private static void closeQuietly(java.io.Closeable c) {
        try {
            c.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }
}

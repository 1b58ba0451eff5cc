package org.tinysep.mailmanager.internal;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

/**
 * A real SMTP server on 127.0.0.1 that refuses, for good (550), every recipient whose address starts "nobody", and
 * answers {@code 552 5.2.2 mailbox full} at RCPT for every address starting "full" while {@link #mailboxFull} is set
 * (RFC 5321 4.5.3.1.10: a temporary failure).
 */
final class RefusingSmtpServer implements AutoCloseable {

    static final String FULL = "552 5.2.2 mailbox full";

    /** Every recipient the server took a message for, once per message. */
    final List<String> acceptedRecipients = new CopyOnWriteArrayList<>();
    volatile boolean mailboxFull = true;
    private final ServerSocket server;
    private final ExecutorService thread = Executors.newSingleThreadExecutor();

    RefusingSmtpServer() throws IOException {
        server = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        thread.execute(this::serve);
    }

    int port() {
        return server.getLocalPort();
    }

    private void serve() {
        while (!server.isClosed()) {
            try (Socket c = server.accept()) {
                c.setSoTimeout(5000);
                session(new BufferedReader(new InputStreamReader(c.getInputStream(), StandardCharsets.US_ASCII)),
                        c.getOutputStream());
            } catch (IOException e) {
                // closed, or the client went away
            }
        }
    }

    private void session(BufferedReader in, OutputStream out) throws IOException {
        reply(out, "220 refusing ESMTP");
        List<String> rcpt = new CopyOnWriteArrayList<>();
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            String verb = line.length() >= 4 ? line.substring(0, 4).toUpperCase() : line;
            if (verb.equals("RCPT") && line.toLowerCase().contains("<nobody")) {
                reply(out, "550 5.1.1 no such user");
            } else if (verb.equals("RCPT") && line.toLowerCase().contains("<full") && mailboxFull) {
                reply(out, FULL);
            } else if (verb.equals("RCPT")) {
                rcpt.add(line.substring(line.indexOf('<') + 1, line.indexOf('>')));
                reply(out, "250 ok");
            } else if (verb.equals("DATA") && rcpt.isEmpty()) {
                reply(out, "554 5.5.1 no valid recipients");
            } else if (verb.equals("DATA")) {
                reply(out, "354 go ahead");
                while (!".".equals(in.readLine())) {
                    // skip the content
                }
                acceptedRecipients.addAll(rcpt);
                rcpt.clear();
                reply(out, "250 accepted");
            } else if (verb.equals("QUIT")) {
                reply(out, "221 bye");
                return;
            } else {
                if (verb.equals("RSET") || verb.equals("MAIL")) {
                    rcpt.clear();
                }
                reply(out, verb.equals("EHLO") ? "250 refusing" : "250 ok");
            }
        }
    }

    private static void reply(OutputStream out, String text) throws IOException {
        out.write((text + "\r\n").getBytes(StandardCharsets.US_ASCII));
        out.flush();
    }

    @Override
    public void close() throws IOException {
        server.close();
        thread.shutdownNow();
    }
}

package org.tinysep.mailmanager.internal;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

/**
 * What the Mail Manager's own test SMTP servers ({@link RefusingSmtpServer}, {@link TlsSmtpServer}) share, written
 * once: a real server socket on 127.0.0.1 served by one thread (one client at a time), and the plain SMTP dialogue —
 * RCPT records the address, MAIL and RSET start a new envelope, DATA takes the message for the recorded recipients,
 * QUIT ends, anything else is answered {@code 250 ok}. A subclass answers the commands it treats otherwise
 * ({@link #answer}), may switch the connection to TLS ({@link #upgrade}) and records what it took ({@link #accept}).
 */
abstract class TestSmtpServer implements AutoCloseable {

    private final ServerSocket server;
    private final ExecutorService thread = Executors.newSingleThreadExecutor();

    TestSmtpServer(ServerSocket server) {
        this.server = server;
    }

    /** Starts accepting clients: the subclass calls it last in its constructor, once its own fields are set. */
    final void listen() {
        thread.execute(this::serve);
    }

    final int port() {
        return server.getLocalPort();
    }

    private void serve() {
        while (!server.isClosed()) {
            try (Socket c = server.accept()) {
                c.setSoTimeout(5000);
                session(c);
            } catch (IOException e) {
                // closed, the client went away (or refused the certificate)
            }
        }
    }

    /** Serves one accepted client (the socket is closed afterwards), usually by {@link #converse}. */
    abstract void session(Socket client) throws IOException;

    /**
     * @return the reply to this command instead of the plain dialogue's, or null for the plain dialogue's
     */
    abstract String answer(String verb, String line, List<String> rcpt, boolean secure);

    /**
     * Called after {@link #answer} replied to {@code line}. @return the connection to go on with inside TLS (its
     * dialogue starts without a greeting), or null to stay on this one
     */
    Socket upgrade(String line, Socket socket, boolean secure) throws IOException {
        return null;
    }

    /** Records a message taken for {@code rcpt} (over TLS if {@code secure}). */
    abstract void accept(List<String> rcpt, boolean secure);

    /** Speaks SMTP with one client until QUIT or the end of the connection; greets first unless greeting is null. */
    final void converse(Socket socket, boolean secure, String greeting) throws IOException {
        BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(),
                StandardCharsets.US_ASCII));
        OutputStream out = socket.getOutputStream();
        if (greeting != null) {
            reply(out, greeting);
        }
        List<String> rcpt = new ArrayList<>();
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            String verb = (line.length() >= 4 ? line.substring(0, 4) : line).toUpperCase(Locale.ROOT);
            String special = answer(verb, line, rcpt, secure);
            if (special != null) {
                reply(out, special);
                Socket secured = upgrade(line, socket, secure);
                if (secured != null) {
                    converse(secured, true, null);
                    return;
                }
            } else if (verb.equals("RCPT")) {
                rcpt.add(line.substring(line.indexOf('<') + 1, line.indexOf('>')));
                reply(out, "250 ok");
            } else if (verb.equals("DATA")) {
                reply(out, "354 go ahead");
                while (!".".equals(in.readLine())) {
                    // skip the content
                }
                accept(rcpt, secure);
                rcpt.clear();
                reply(out, "250 accepted");
            } else if (verb.equals("QUIT")) {
                reply(out, "221 bye");
                return;
            } else {
                if (verb.equals("RSET") || verb.equals("MAIL")) {
                    rcpt.clear();
                }
                reply(out, "250 ok");
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
        try {
            thread.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

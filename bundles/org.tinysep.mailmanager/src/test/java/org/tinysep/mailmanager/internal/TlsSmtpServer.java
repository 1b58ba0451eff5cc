package org.tinysep.mailmanager.internal;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocket;

/**
 * A real SMTP server on 127.0.0.1 speaking TLS with the key of a PKCS12 keystore (made by {@code keytool} in the
 * test): implicit TLS from the first byte ({@code smtps}), or plain with {@code STARTTLS} offered and required
 * before MAIL. Records the recipients of every message it took, and whether that happened inside TLS.
 */
final class TlsSmtpServer implements AutoCloseable {

    /** Recipients of accepted messages, each prefixed "tls:" or "plain:" (how the message travelled). */
    final List<String> accepted = new CopyOnWriteArrayList<>();
    /** Handshakes that failed (the client refused the certificate). */
    final List<String> handshakeFailures = new CopyOnWriteArrayList<>();
    private final boolean implicit;
    private final SSLContext tls;
    private final ServerSocket server;
    private final ExecutorService thread = Executors.newSingleThreadExecutor();

    /**
     * @param implicit true: TLS from the first byte; false: STARTTLS
     */
    TlsSmtpServer(Path pkcs12, char[] password, boolean implicit) throws Exception {
        this.implicit = implicit;
        KeyStore ks = KeyStore.getInstance("PKCS12");
        try (InputStream in = Files.newInputStream(pkcs12)) {
            ks.load(in, password);
        }
        KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
        kmf.init(ks, password);
        tls = SSLContext.getInstance("TLS");
        tls.init(kmf.getKeyManagers(), null, null);
        server = implicit ? tls.getServerSocketFactory().createServerSocket(0, 5, InetAddress.getLoopbackAddress())
                : new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        thread.execute(this::serve);
    }

    int port() {
        return server.getLocalPort();
    }

    private void serve() {
        while (!server.isClosed()) {
            try (Socket c = server.accept()) {
                c.setSoTimeout(5000);
                if (c instanceof SSLSocket s) {
                    handshake(s);
                }
                session(c, implicit);
            } catch (IOException e) {
                // closed, the client went away or refused the certificate
            }
        }
    }

    private void handshake(SSLSocket s) throws IOException {
        try {
            s.startHandshake();
        } catch (IOException e) {
            handshakeFailures.add(String.valueOf(e.getMessage()));
            throw e;
        }
    }

    private void session(Socket socket, boolean secure) throws IOException {
        BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(),
                StandardCharsets.US_ASCII));
        OutputStream out = socket.getOutputStream();
        if (!secure || implicit) {
            reply(out, "220 tls-test ESMTP");
        }
        List<String> rcpt = new CopyOnWriteArrayList<>();
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            String verb = line.length() >= 4 ? line.substring(0, 4).toUpperCase() : line.toUpperCase();
            if (verb.equals("EHLO")) {
                reply(out, secure ? "250 tls-test" : "250-tls-test\r\n250 STARTTLS");
            } else if (line.equalsIgnoreCase("STARTTLS") && !secure) {
                reply(out, "220 2.0.0 ready to start TLS");
                SSLSocket s = (SSLSocket) tls.getSocketFactory().createSocket(socket, "127.0.0.1", socket.getPort(),
                        false);
                s.setUseClientMode(false);
                handshake(s);
                session(s, true);
                return;
            } else if (verb.equals("MAIL") && !secure) {
                reply(out, "530 5.7.0 must issue a STARTTLS command first");
            } else if (verb.equals("RCPT")) {
                rcpt.add(line.substring(line.indexOf('<') + 1, line.indexOf('>')));
                reply(out, "250 ok");
            } else if (verb.equals("DATA")) {
                reply(out, "354 go ahead");
                while (!".".equals(in.readLine())) {
                    // skip the content
                }
                rcpt.forEach(r -> accepted.add((secure ? "tls:" : "plain:") + r));
                rcpt.clear();
                reply(out, "250 accepted");
            } else if (verb.equals("QUIT")) {
                reply(out, "221 bye");
                return;
            } else {
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

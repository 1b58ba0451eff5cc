package org.tinysep.mailmanager.internal;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocket;

/**
 * A real SMTP server on 127.0.0.1 speaking TLS with the key of a PKCS12 keystore (made by {@code keytool} in the
 * test): implicit TLS from the first byte ({@code smtps}), or plain with {@code STARTTLS} offered and required
 * before MAIL. Records the recipients of every message it took, and whether that happened inside TLS.
 */
final class TlsSmtpServer extends TestSmtpServer {

    /** Recipients of accepted messages, each prefixed "tls:" or "plain:" (how the message travelled). */
    final List<String> accepted = new CopyOnWriteArrayList<>();
    /** Handshakes that failed (the client refused the certificate). */
    final List<String> handshakeFailures = new CopyOnWriteArrayList<>();
    private final boolean implicit;
    private final SSLContext tls;

    /**
     * @param implicit true: TLS from the first byte; false: STARTTLS
     */
    TlsSmtpServer(Path pkcs12, char[] password, boolean implicit) throws Exception {
        this(context(pkcs12, password), implicit);
    }

    private TlsSmtpServer(SSLContext tls, boolean implicit) throws IOException {
        super(implicit ? tls.getServerSocketFactory().createServerSocket(0, 5, InetAddress.getLoopbackAddress())
                : new ServerSocket(0, 5, InetAddress.getLoopbackAddress()));
        this.implicit = implicit;
        this.tls = tls;
        listen();
    }

    private static SSLContext context(Path pkcs12, char[] password) throws Exception {
        KeyStore ks = KeyStore.getInstance("PKCS12");
        try (InputStream in = Files.newInputStream(pkcs12)) {
            ks.load(in, password);
        }
        KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
        kmf.init(ks, password);
        SSLContext tls = SSLContext.getInstance("TLS");
        tls.init(kmf.getKeyManagers(), null, null);
        return tls;
    }

    @Override
    void session(Socket client) throws IOException {
        if (client instanceof SSLSocket s) {
            handshake(s);
        }
        converse(client, implicit, "220 tls-test ESMTP");
    }

    private void handshake(SSLSocket s) throws IOException {
        try {
            s.startHandshake();
        } catch (IOException e) {
            handshakeFailures.add(String.valueOf(e.getMessage()));
            throw e;
        }
    }

    @Override
    String answer(String verb, String line, List<String> rcpt, boolean secure) {
        if (verb.equals("EHLO")) {
            return secure ? "250 tls-test" : "250-tls-test\r\n250 STARTTLS";
        } else if (startTls(line, secure)) {
            return "220 2.0.0 ready to start TLS";
        } else if (verb.equals("MAIL") && !secure) {
            return "530 5.7.0 must issue a STARTTLS command first";
        }
        return null;
    }

    @Override
    Socket upgrade(String line, Socket socket, boolean secure) throws IOException {
        if (!startTls(line, secure)) {
            return null;
        }
        SSLSocket s = (SSLSocket) tls.getSocketFactory().createSocket(socket, "127.0.0.1", socket.getPort(), false);
        s.setUseClientMode(false);
        handshake(s);
        return s;
    }

    private static boolean startTls(String line, boolean secure) {
        return line.equalsIgnoreCase("STARTTLS") && !secure;
    }

    @Override
    void accept(List<String> rcpt, boolean secure) {
        rcpt.forEach(r -> accepted.add((secure ? "tls:" : "plain:") + r));
    }
}

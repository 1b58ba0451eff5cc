package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.net.URI;
import java.util.Optional;
import javax.net.ssl.SSLException;
import javax.net.ssl.SSLSocket;

/**
 * Names a refused client certificate, which Paho reports only as "Broken pipe" or "Connection reset": with TLS 1.3
 * the broker checks the client's certificate after the client has written its last handshake message and closes
 * the connection, often before the client has read the broker's alert. After a failed connection to an
 * {@code ssl://} broker the bridge does the handshake alone and waits for the broker's answer: its alert
 * ({@code certificate_required}, {@code unknown_ca} …), or the connection closed right after this flat's certificate
 * was sent (refused), or nothing while it waits for CONNECT (accepted: Paho's words stand). Bounded:
 * {@value #TIMEOUT_MILLIS} ms to connect and as long to read.
 */
final class TlsProbe {

    static final int TIMEOUT_MILLIS = 3000;

    private TlsProbe() {
    }

    /** @return why the broker refused this flat's certificate (or the lack of one), in words, or empty */
    static Optional<String> clientCertificateRefusal(Settings s) {
        URI u = URI.create(s.brokerUrl());
        try (SSLSocket socket = (SSLSocket) Tls.socketFactory(s).createSocket()) {
            socket.connect(new InetSocketAddress(u.getHost(), u.getPort() < 0 ? 8883 : u.getPort()), TIMEOUT_MILLIS);
            socket.setSoTimeout(TIMEOUT_MILLIS);
            socket.startHandshake();
            if (socket.getInputStream().read() < 0) {
                return closed(s, "the broker closed the connection");
            }
            return Optional.empty();
        } catch (SSLException e) {
            String message = String.valueOf(e.getMessage());
            return Trouble.aboutClientCertificate(message) ? Optional.of(Trouble.tls(message)) : Optional.empty();
        } catch (SocketTimeoutException e) {
            return Optional.empty(); // the broker waits for CONNECT: it took the certificate
        } catch (SocketException e) {
            return closed(s, String.valueOf(e.getMessage()));
        } catch (IOException | RuntimeException e) {
            return Optional.empty();
        }
    }

    private static Optional<String> closed(Settings s, String how) {
        if (s.keyStore() == null) {
            return Optional.empty();
        }
        return Optional.of("TLS failed: the broker refused this flat's client certificate (" + how
                + " right after the certificate from " + s.keyStore() + " was sent; is it signed by a CA the broker"
                + " trusts, and still valid?)");
    }
}

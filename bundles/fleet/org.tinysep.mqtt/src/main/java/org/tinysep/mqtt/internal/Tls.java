package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import javax.net.SocketFactory;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;

/** The TLS socket factory of an {@code ssl://} broker: its trust store and, optionally, this flat's client certificate. */
final class Tls {

    private Tls() {
    }

    /** @throws IOException in plain words: which file, what is wrong */
    static SocketFactory socketFactory(Settings s) throws IOException {
        try {
            TrustManagerFactory tmf = null;
            if (s.trustStore() != null) {
                tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
                tmf.init(load(s.trustStore(), s.trustStorePassword().toCharArray(), "trust store"));
            }
            KeyManagerFactory kmf = null;
            if (s.keyStore() != null) {
                char[] pw = Secrets.firstLine(s.keyStorePasswordFile(), "key store password").toCharArray();
                kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
                kmf.init(load(s.keyStore(), pw, "key store"), pw);
            }
            SSLContext ctx = SSLContext.getInstance("TLS");
            ctx.init(kmf == null ? null : kmf.getKeyManagers(), tmf == null ? null : tmf.getTrustManagers(), null);
            return ctx.getSocketFactory();
        } catch (GeneralSecurityException e) {
            throw new IOException("TLS cannot be set up: " + e.getMessage());
        }
    }

    private static KeyStore load(Path file, char[] password, String what) throws IOException, GeneralSecurityException {
        if (!Files.exists(file)) {
            throw new IOException("the " + what + " " + file + " does not exist");
        }
        String type = file.toString().endsWith(".jks") ? "JKS" : "PKCS12";
        KeyStore ks = KeyStore.getInstance(type);
        try (InputStream in = Files.newInputStream(file)) {
            ks.load(in, password);
        } catch (IOException e) {
            throw new IOException("the " + what + " " + file + " cannot be read (wrong password or not " + type + "): "
                    + e.getMessage());
        }
        return ks;
    }
}

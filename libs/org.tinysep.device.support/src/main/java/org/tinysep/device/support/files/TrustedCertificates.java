package org.tinysep.device.support.files;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.cert.Certificate;
import java.security.cert.CertificateFactory;
import java.util.Collection;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocketFactory;
import javax.net.ssl.TrustManagerFactory;

/**
 * TLS that trusts exactly the certificates of one PEM file (a server with its own certificate: the Mail Manager's
 * SMTP server, the push channel's ntfy server): PEM → key store → trust managers → TLS context. A certificate not
 * in the file is refused; checking the server's name against its certificate stays the caller's job (the mail
 * library's {@code ssl.checkserveridentity}, {@code HttpsURLConnection}'s host name check).
 */
public final class TrustedCertificates {

    private TrustedCertificates() {
    }

    /**
     * @param pem a file with one or more PEM certificates; read at every call, so a replaced file counts at once
     * @return a socket factory trusting only the certificates in {@code pem}
     * @throws GeneralSecurityException when the file holds no certificate (its path in the message) or one that
     *                                  cannot be read
     */
    public static SSLSocketFactory factory(Path pem) throws IOException, GeneralSecurityException {
        Collection<? extends Certificate> certs;
        try (InputStream in = Files.newInputStream(pem)) {
            certs = CertificateFactory.getInstance("X.509").generateCertificates(in);
        }
        if (certs.isEmpty()) {
            throw new GeneralSecurityException("no certificate in " + pem);
        }
        KeyStore store = KeyStore.getInstance(KeyStore.getDefaultType());
        store.load(null, null);
        int i = 0;
        for (Certificate c : certs) {
            store.setCertificateEntry("trusted-" + i++, c);
        }
        TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
        tmf.init(store);
        SSLContext tls = SSLContext.getInstance("TLS");
        tls.init(null, tmf.getTrustManagers(), null);
        return tls.getSocketFactory();
    }
}

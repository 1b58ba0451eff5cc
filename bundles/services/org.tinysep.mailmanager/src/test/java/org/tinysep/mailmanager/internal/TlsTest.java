package org.tinysep.mailmanager.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.util.List;
import java.util.Map;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * TLS and STARTTLS against a real TLS SMTP server ({@link SmtpSink#tls}) whose self-signed certificates are made
 * here by {@code keytool}: delivered when the certificate is in the configured {@code trustedCertificates} file;
 * refused (never sent in clear, retried, the reason visible) when it is another certificate, when no file is
 * configured (the Java runtime does not know it), and when the certificate names another host.
 */
class TlsTest {

    private static final char[] PASSWORD = "changeit".toCharArray();
    @TempDir
    static Path keys;
    /** Server key for 127.0.0.1/localhost, its certificate; a second one (the wrong one); one for other.test. */
    static Path serverStore;
    static Path serverPem;
    static Path otherPem;
    static Path wrongNameStore;
    static Path wrongNamePem;

    @TempDir
    Path spool;
    private final MailHarness h = new MailHarness();
    private SmtpSink server;

    @BeforeAll
    static void certificates() throws Exception {
        serverStore = keyPair("server", "CN=localhost", "san=ip:127.0.0.1,dns:localhost");
        serverPem = pem(serverStore, "server");
        otherPem = pem(keyPair("other", "CN=localhost", "san=ip:127.0.0.1,dns:localhost"), "other");
        wrongNameStore = keyPair("wrongname", "CN=other.test", "san=dns:other.test");
        wrongNamePem = pem(wrongNameStore, "wrongname");
    }

    private static Path keyPair(String alias, String dname, String san) throws Exception {
        Path store = keys.resolve(alias + ".p12");
        keytool("-genkeypair", "-alias", alias, "-keyalg", "EC", "-groupname", "secp256r1", "-dname", dname,
                "-ext", san, "-validity", "2", "-storetype", "PKCS12", "-keystore", store.toString(),
                "-storepass", new String(PASSWORD), "-keypass", new String(PASSWORD));
        return store;
    }

    private static Path pem(Path store, String alias) throws Exception {
        Path pem = keys.resolve(alias + ".pem");
        keytool("-exportcert", "-rfc", "-alias", alias, "-keystore", store.toString(), "-storetype", "PKCS12",
                "-storepass", new String(PASSWORD), "-file", pem.toString());
        return pem;
    }

    private static void keytool(String... args) throws Exception {
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin",
                "keytool").toString()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (p.waitFor() != 0) {
            throw new IOException("keytool failed: " + out);
        }
    }

    private static SSLContext context(Path pkcs12) throws Exception {
        KeyStore ks = KeyStore.getInstance("PKCS12");
        try (InputStream in = Files.newInputStream(pkcs12)) {
            ks.load(in, PASSWORD);
        }
        KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
        kmf.init(ks, PASSWORD);
        SSLContext tls = SSLContext.getInstance("TLS");
        tls.init(kmf.getKeyManagers(), null, null);
        return tls;
    }

    /** Recipients of accepted messages, each prefixed "tls:" or "plain:" (how the message travelled). */
    private List<String> accepted() {
        return server.messages().stream()
                .flatMap(m -> m.to().stream().map(r -> (m.tls() ? "tls:" : "plain:") + r)).toList();
    }

    @AfterEach
    void tearDown() throws IOException {
        h.close();
        if (server != null) {
            server.close();
        }
    }

    private MailManagerProvider start(boolean implicit, Path store, Path trusted) throws Exception {
        server = new SmtpSink().tls(context(store), implicit).start();
        Map<String, Object> c = MailHarness.smtp(server.port(), spool);
        c.put("security", implicit ? "TLS" : "STARTTLS");
        c.put("retryInitialSeconds", 60);
        c.put("retryMaxSeconds", 60);
        if (trusted != null) {
            c.put("trustedCertificates", trusted.toString());
        }
        return h.start(c).provider();
    }

    @Test
    void implicitTlsDeliversWhenTheCertificateIsTrusted() throws Exception {
        MailManagerProvider mail = start(true, serverStore, serverPem);
        String id = mail.sendTo(List.of("anna@care.test"), "Alert over TLS", "body");
        MailHarness.await("delivered", () -> accepted().contains("tls:anna@care.test"));
        MailHarness.await("outcome SENT", () -> mail.delivery(id).map(MailDelivery::outcome).orElse(null)
                == MailDelivery.Outcome.SENT);
        assertEquals(List.of("tls:anna@care.test"), accepted());
    }

    @Test
    void startTlsUpgradesBeforeTheMessageAndDelivers() throws Exception {
        MailManagerProvider mail = start(false, serverStore, serverPem);
        mail.send("Alert over STARTTLS", "body");
        MailHarness.await("delivered", () -> accepted().size() == 2);
        assertEquals(List.of("tls:carer@care.test", "tls:family@kin.test"), accepted());
    }

    @Test
    void anotherCertificateIsRefusedOverTls() throws Exception {
        refused(start(true, serverStore, otherPem));
    }

    @Test
    void anotherCertificateIsRefusedOverStartTls() throws Exception {
        refused(start(false, serverStore, otherPem));
    }

    @Test
    void anUnknownSelfSignedCertificateIsRefusedWithoutATrustFile() throws Exception {
        refused(start(true, serverStore, null));
    }

    @Test
    void aTrustedCertificateForAnotherHostIsRefused() throws Exception {
        MailManagerProvider mail = start(true, wrongNameStore, wrongNamePem);
        String detail = refused(mail);
        assertTrue(detail.contains("127.0.0.1") || detail.toLowerCase().contains("certificate"), detail);
    }

    /** @return the outcome detail: retrying, nothing delivered, nothing sent in clear */
    private String refused(MailManagerProvider mail) {
        String id = mail.sendTo(List.of("anna@care.test"), "Alert", "body");
        MailHarness.await("RETRYING", () -> mail.status() == MailStatus.RETRYING);
        MailDelivery d = mail.delivery(id).orElseThrow();
        assertEquals(MailDelivery.Outcome.RETRYING, d.outcome(), d.toString());
        assertTrue(d.detail().contains("delivery failed temporarily"), d.detail());
        assertTrue(accepted().isEmpty(), accepted().toString());
        MailHarness.await("the server saw the client refuse the handshake", () -> !server.handshakeFailures().isEmpty());
        return d.detail();
    }
}

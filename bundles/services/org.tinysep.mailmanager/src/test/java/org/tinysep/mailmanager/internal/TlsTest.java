package org.tinysep.mailmanager.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;

/**
 * TLS and STARTTLS against a real TLS SMTP server ({@link TlsSmtpServer}) whose self-signed certificates are made
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
    private TlsSmtpServer server;

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

    @AfterEach
    void tearDown() throws IOException {
        h.close();
        if (server != null) {
            server.close();
        }
    }

    private MailManagerProvider start(boolean implicit, Path store, Path trusted) throws Exception {
        server = new TlsSmtpServer(store, PASSWORD, implicit);
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
        MailHarness.await("delivered", () -> server.accepted.contains("tls:anna@care.test"));
        MailHarness.await("outcome SENT", () -> mail.delivery(id).map(MailDelivery::outcome).orElse(null)
                == MailDelivery.Outcome.SENT);
        assertEquals(List.of("tls:anna@care.test"), server.accepted);
    }

    @Test
    void startTlsUpgradesBeforeTheMessageAndDelivers() throws Exception {
        MailManagerProvider mail = start(false, serverStore, serverPem);
        mail.send("Alert over STARTTLS", "body");
        MailHarness.await("delivered", () -> server.accepted.size() == 2);
        assertEquals(List.of("tls:carer@care.test", "tls:family@kin.test"), server.accepted);
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
        assertTrue(server.accepted.isEmpty(), server.accepted.toString());
        return d.detail();
    }
}

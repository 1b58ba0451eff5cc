package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.testsupport.mqtt.ClientCertificates;
import org.tinysep.testsupport.mqtt.Mosquitto;

/**
 * The Paho link against a real Mosquitto that requires client certificates ({@code require_certificate true});
 * certificates made by openssl in the test ({@link ClientCertificates}): with the flat's certificate it connects and
 * publishes; without one, or with one the broker's CA did not sign, it is refused in plain words, as "refused"
 * (the bridge device shows ERROR) and without a stack trace.
 */
class ClientCertificateLinkTest extends LinkTestSupport {

    private static final String PASSWORD = "flat-key-pw";

    private Link link(Mosquitto broker, Path keyStore) throws Exception {
        Map<String, String> c = new HashMap<>();
        c.put("brokerUrl", broker.url());
        c.put("flatId", "f1");
        c.put("trustStore", broker.trustStore().toString());
        if (keyStore != null) {
            Path pw = var.resolve("key.password");
            Files.writeString(pw, PASSWORD + "\n");
            c.put("keyStore", keyStore.toString());
            c.put("keyStorePasswordFile", pw.toString());
        }
        Settings s = Settings.parse(c, var);
        return new Link(s, new Topics(s.topicPrefix(), s.flatId(), s.discoveryPrefix()), executor, events);
    }

    /** Connects with this key store (null: none) and checks the refusal's words: one line, no exception name. */
    private void refused(Mosquitto broker, Path keyStore, String start, String end) throws Exception {
        Link link = link(broker, keyStore);
        link.connect();
        String failed = events.next();
        assertTrue(failed.startsWith("failed (refused): TLS failed: " + start) && failed.endsWith(end), failed);
        assertTrue(!failed.contains("\n") && !failed.contains("Exception") && !failed.contains("\tat "), failed);
        link.close(2000);
    }

    @Test
    void connectsWithItsCertificate() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().requireClientCertificate(true).start()) {
            Path keyStore = ClientCertificates.issue(broker, var.resolve("certs"), "f1", PASSWORD);
            Link link = link(broker, keyStore);
            link.connect();
            assertEquals("connected", events.next(), broker.log());
            link.publish(Message.state("tinysep/f1/status", "online"));
            assertEquals("published tinysep/f1/status true", events.next());
            link.close(2000);
        }
    }

    @Test
    void isRefusedInWordsWithoutACertificate() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().requireClientCertificate(true).start()) {
            refused(broker, null, "the broker requires a client certificate (",
                    "; set keyStore and keyStorePasswordFile)");
        }
    }

    @Test
    void isRefusedInWordsWithAnUntrustedCertificate() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().requireClientCertificate(true).start()) {
            refused(broker, ClientCertificates.selfSigned(var.resolve("certs"), "f1", PASSWORD),
                    "the broker refused this flat's client certificate (",
                    "; is it signed by a CA the broker trusts, and still valid?)");
        }
    }
}

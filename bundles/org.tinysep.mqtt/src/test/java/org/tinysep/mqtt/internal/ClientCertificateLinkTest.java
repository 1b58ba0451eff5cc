package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.testsupport.mqtt.ClientCertificates;
import org.tinysep.testsupport.mqtt.Mosquitto;

/**
 * The Paho link against a real Mosquitto that requires client certificates ({@code require_certificate true});
 * certificates made by openssl in the test ({@link ClientCertificates}): with the flat's certificate it connects and
 * publishes; without one, or with one the broker's CA did not sign, it is refused in plain words, as "refused"
 * (retrying does not help) and without a stack trace.
 */
class ClientCertificateLinkTest {

    private static final String PASSWORD = "flat-key-pw";

    @TempDir
    Path var;

    private final ExecutorService executor = Executors.newSingleThreadExecutor();
    private final LinkedBlockingQueue<String> events = new LinkedBlockingQueue<>();

    @AfterEach
    void stop() {
        executor.shutdownNow();
    }

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
        Topics topics = new Topics(s.topicPrefix(), s.flatId(), s.discoveryPrefix());
        return new Link(s, topics, executor, new Link.Events() {
            @Override
            public void connected(int generation) {
                events.add("connected");
            }

            @Override
            public void failed(int generation, String why, boolean refused) {
                events.add("failed" + (refused ? " (refused)" : "") + ": " + why);
            }

            @Override
            public void lost(int generation, String why) {
                events.add("lost: " + why);
            }

            @Override
            public void published(int generation, Message m, boolean ok) {
                events.add("published " + m.topic() + " " + ok);
            }

            @Override
            public void command(String topic, byte[] payload) {
                events.add("command " + topic + " " + new String(payload, StandardCharsets.UTF_8));
            }
        });
    }

    private String next() throws InterruptedException {
        String e = events.poll(60, TimeUnit.SECONDS);
        return e == null ? "(nothing within 60 s)" : e;
    }

    /** One line, no exception class names or stack frames. */
    private static void plainWords(String s) {
        assertTrue(!s.contains("\n") && !s.contains("Exception") && !s.contains("\tat "), s);
    }

    @Test
    void connectsWithItsCertificate() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().requireClientCertificate(true).start()) {
            Path keyStore = ClientCertificates.issue(broker, var.resolve("certs"), "f1", PASSWORD);
            Link link = link(broker, keyStore);
            link.connect();
            assertEquals("connected", next(), broker.log());
            link.publish(Message.state("tinysep/f1/status", "online"));
            assertEquals("published tinysep/f1/status true", next());
            link.close(2000);
        }
    }

    @Test
    void isRefusedInWordsWithoutACertificate() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().requireClientCertificate(true).start()) {
            Link link = link(broker, null);
            link.connect();
            String failed = next();
            assertTrue(failed.startsWith("failed (refused): TLS failed: the broker requires a client certificate ("),
                    failed);
            assertTrue(failed.endsWith("; set keyStore and keyStorePasswordFile)"), failed);
            plainWords(failed);
            link.close(2000);
        }
    }

    @Test
    void isRefusedInWordsWithAnUntrustedCertificate() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().requireClientCertificate(true).start()) {
            Path keyStore = ClientCertificates.selfSigned(var.resolve("certs"), "f1", PASSWORD);
            Link link = link(broker, keyStore);
            link.connect();
            String failed = next();
            assertTrue(failed.startsWith("failed (refused): TLS failed: the broker refused this flat's client certificate ("),
                    failed);
            assertTrue(failed.endsWith("; is it signed by a CA the broker trusts, and still valid?)"), failed);
            plainWords(failed);
            link.close(2000);
        }
    }
}

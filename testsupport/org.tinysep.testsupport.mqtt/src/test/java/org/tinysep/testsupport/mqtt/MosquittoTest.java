package org.tinysep.testsupport.mqtt;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.security.KeyStore;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;

import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;

import org.eclipse.paho.mqttv5.client.IMqttMessageListener;
import org.eclipse.paho.mqttv5.client.MqttClient;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttSubscription;
import org.junit.jupiter.api.Test;

class MosquittoTest {

    @Test
    void publishesAndDeliversRetainedMessages() throws Exception {
        try (Mosquitto broker = Mosquitto.startDefault()) {
            assertTrue(broker.url().startsWith("tcp://127.0.0.1:"));
            assertEquals("hello", roundTrip(broker, options(), "t/a", "hello"));
        }
    }

    @Test
    void stopsAndStartsAgainOnTheSamePort() throws Exception {
        try (Mosquitto broker = Mosquitto.startDefault()) {
            int port = broker.port();
            broker.stop();
            assertFalse(broker.isRunning());
            MqttClient c = new MqttClient(broker.url(), "down", new MemoryPersistence());
            assertThrows(MqttException.class, () -> c.connect(options()));
            c.close();
            broker.start();
            assertEquals(port, broker.port());
            assertEquals("again", roundTrip(broker, options(), "t/b", "again"));
        }
    }

    @Test
    void persistenceKeepsRetainedMessagesAcrossARestart() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().persistence(true).start()) {
            MqttClient c = new MqttClient(broker.url(), "keep", new MemoryPersistence());
            c.connect(options());
            c.publish("t/kept", "value".getBytes(StandardCharsets.UTF_8), 1, true);
            c.disconnect();
            c.close();
            broker.stop();
            broker.start();
            BlockingQueue<String> got = new ArrayBlockingQueue<>(10);
            MqttClient s = new MqttClient(broker.url(), "read", new MemoryPersistence());
            s.connect(options());
            subscribe(s, "t/kept", got);
            assertEquals("value", got.poll(20, TimeUnit.SECONDS));
            s.disconnect();
            s.close();
        }
    }

    @Test
    void passwordFileRefusesAnonymousAndWrongPasswords() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().user("flat1", "s3cret").start()) {
            MqttClient anonymous = new MqttClient(broker.url(), "anon", new MemoryPersistence());
            assertThrows(MqttException.class, () -> anonymous.connect(options()));
            anonymous.close();
            MqttConnectionOptions wrong = options();
            wrong.setUserName("flat1");
            wrong.setPassword("wrong".getBytes(StandardCharsets.UTF_8));
            MqttClient bad = new MqttClient(broker.url(), "bad", new MemoryPersistence());
            assertThrows(MqttException.class, () -> bad.connect(wrong));
            bad.close();
            MqttConnectionOptions right = options();
            right.setUserName("flat1");
            right.setPassword("s3cret".getBytes(StandardCharsets.UTF_8));
            assertEquals("in", roundTrip(broker, right, "t/c", "in"));
        }
    }

    @Test
    void tlsWithTheGeneratedTrustStore() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().tls(true).start()) {
            assertTrue(broker.url().startsWith("ssl://127.0.0.1:"));
            KeyStore trust = KeyStore.getInstance("PKCS12");
            try (InputStream in = Files.newInputStream(broker.trustStore())) {
                trust.load(in, Mosquitto.TRUST_STORE_PASSWORD.toCharArray());
            }
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(trust);
            SSLContext ssl = SSLContext.getInstance("TLS");
            ssl.init(null, tmf.getTrustManagers(), null);
            MqttConnectionOptions o = options();
            o.setSocketFactory(ssl.getSocketFactory());
            assertEquals("secure", roundTrip(broker, o, "t/d", "secure"));
            // without the trust store the self-signed certificate is refused
            MqttClient untrusted = new MqttClient(broker.url(), "untrusted", new MemoryPersistence());
            assertThrows(MqttException.class, () -> untrusted.connect(options()));
            untrusted.close();
        }
    }

    private static MqttConnectionOptions options() {
        MqttConnectionOptions o = new MqttConnectionOptions();
        o.setConnectionTimeout(10);
        o.setAutomaticReconnect(false);
        return o;
    }

    /** Paho 1.2.5's MqttClient.subscribe(String, int, listener) recurses forever: use the array form. */
    private static void subscribe(MqttClient c, String topic, BlockingQueue<String> got) throws MqttException {
        c.subscribe(new MqttSubscription[] {new MqttSubscription(topic, 1)},
                new IMqttMessageListener[] {(t, m) -> got.add(new String(m.getPayload(), StandardCharsets.UTF_8))});
    }

    private static String roundTrip(Mosquitto broker, MqttConnectionOptions o, String topic, String text)
            throws Exception {
        BlockingQueue<String> got = new ArrayBlockingQueue<>(10);
        MqttClient c = new MqttClient(broker.url(), "rt-" + topic.replace('/', '-'), new MemoryPersistence());
        c.connect(o);
        try {
            subscribe(c, topic, got);
            c.publish(topic, text.getBytes(StandardCharsets.UTF_8), 1, true);
            return got.poll(20, TimeUnit.SECONDS);
        } finally {
            c.disconnect();
            c.close();
        }
    }
}

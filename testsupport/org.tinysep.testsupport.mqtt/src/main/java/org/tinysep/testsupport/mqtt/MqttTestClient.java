package org.tinysep.testsupport.mqtt;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;
import org.eclipse.paho.mqttv5.client.IMqttMessageListener;
import org.eclipse.paho.mqttv5.client.MqttClient;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttSubscription;

/**
 * A small MQTT v5 client for tests (Eclipse Paho, embedded in this jar so it also works inside an OSGi framework
 * where Paho's own jar cannot be deployed): records every message of its subscriptions and waits for conditions.
 * Its API has no Paho types.
 */
public final class MqttTestClient implements AutoCloseable {

    /** One message as received. */
    public record Received(String topic, String payload, boolean retained, Instant at) {
    }

    private final MqttClient client;
    private final List<Received> received = new ArrayList<>();

    private MqttTestClient(MqttClient client) {
        this.client = client;
    }

    /** @return a connected anonymous client (clean start) */
    public static MqttTestClient connect(String url, String clientId) {
        return builder(url).clientId(clientId).connect();
    }

    public static Builder builder(String url) {
        return new Builder(url);
    }

    /** Subscribes with QoS 1; retained messages of the filters arrive at once. */
    public MqttTestClient subscribe(String... filters) {
        MqttSubscription[] subs = new MqttSubscription[filters.length];
        IMqttMessageListener[] listeners = new IMqttMessageListener[filters.length];
        for (int i = 0; i < filters.length; i++) {
            subs[i] = new MqttSubscription(filters[i], 1);
            listeners[i] = (topic, m) -> {
                synchronized (received) {
                    received.add(new Received(topic, new String(m.getPayload(), StandardCharsets.UTF_8),
                            m.isRetained(), Instant.now()));
                    received.notifyAll();
                }
            };
        }
        try {
            client.subscribe(subs, listeners); // not subscribe(String, int, listener): it recurses in Paho 1.2.5
        } catch (MqttException e) {
            throw new IllegalStateException("cannot subscribe to " + String.join(", ", filters) + ": " + e, e);
        }
        return this;
    }

    /** Publishes with QoS 1 and waits for the broker's acknowledgement. */
    public void publish(String topic, String payload, boolean retained) {
        publish(topic, payload.getBytes(StandardCharsets.UTF_8), retained);
    }

    public void publish(String topic, byte[] payload, boolean retained) {
        try {
            client.publish(topic, payload, 1, retained);
        } catch (MqttException e) {
            throw new IllegalStateException("cannot publish to " + topic + ": " + e, e);
        }
    }

    /** @return every message so far, in arrival order */
    public List<Received> received() {
        synchronized (received) {
            return List.copyOf(received);
        }
    }

    /** @return the messages of one topic so far */
    public List<Received> received(String topic) {
        return received().stream().filter(r -> r.topic().equals(topic)).toList();
    }

    public void clear() {
        synchronized (received) {
            received.clear();
        }
    }

    /**
     * Waits until a message matching {@code condition} has arrived (also one that arrived before the call).
     *
     * @throws AssertionError naming {@code what} and listing what did arrive, after {@code timeout}
     */
    public Received await(String what, Duration timeout, Predicate<Received> condition) {
        Instant deadline = Instant.now().plus(timeout);
        synchronized (received) {
            while (true) {
                for (Received r : received) {
                    if (condition.test(r)) {
                        return r;
                    }
                }
                long left = Duration.between(Instant.now(), deadline).toMillis();
                if (left <= 0) {
                    StringBuilder b = new StringBuilder("no MQTT message " + what + " within " + timeout.toSeconds()
                            + " s; received " + received.size() + ":");
                    received.stream().skip(Math.max(0, received.size() - 40))
                            .forEach(r -> b.append("\n  ").append(r.topic()).append(" ").append(r.payload()));
                    throw new AssertionError(b.toString());
                }
                try {
                    received.wait(Math.min(left, 200));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new AssertionError("interrupted while waiting for " + what);
                }
            }
        }
    }

    /** Waits for a message on {@code topic} whose payload contains {@code text}. */
    public Received await(String topic, String text, Duration timeout) {
        return await("on " + topic + " containing " + text, timeout,
                r -> r.topic().equals(topic) && r.payload().contains(text));
    }

    public boolean isConnected() {
        return client.isConnected();
    }

    @Override
    public void close() {
        try {
            if (client.isConnected()) {
                client.disconnect();
            }
        } catch (MqttException e) {
            // gone anyway
        }
        try {
            client.close();
        } catch (MqttException e) {
            // gone anyway
        }
    }

    /** Connection options of a test client. */
    public static final class Builder {
        private final String url;
        private String clientId = "test-" + System.nanoTime();
        private String user;
        private String password;
        private Path trustStore;
        private String trustStorePassword = Mosquitto.TRUST_STORE_PASSWORD;
        private boolean cleanStart = true;
        private Path keyStore;
        private String keyStorePassword;

        private Builder(String url) {
            this.url = url;
        }

        public Builder clientId(String id) {
            this.clientId = id;
            return this;
        }

        public Builder user(String name, String password) {
            this.user = name;
            this.password = password;
            return this;
        }

        public Builder trustStore(Path store, String password) {
            this.trustStore = store;
            this.trustStorePassword = password;
            return this;
        }

        /** The client's certificate and key (PKCS12), for a broker that requires client certificates. */
        public Builder keyStore(Path store, String password) {
            this.keyStore = store;
            this.keyStorePassword = password;
            return this;
        }

        public Builder cleanStart(boolean on) {
            this.cleanStart = on;
            return this;
        }

        /** @throws IllegalStateException when the broker cannot be reached or refuses */
        public MqttTestClient connect() {
            try {
                MqttClient c = new MqttClient(url, clientId, new MemoryPersistence());
                MqttConnectionOptions o = new MqttConnectionOptions();
                o.setCleanStart(cleanStart);
                o.setConnectionTimeout(10);
                o.setAutomaticReconnect(false);
                if (user != null) {
                    o.setUserName(user);
                    o.setPassword(password.getBytes(StandardCharsets.UTF_8));
                }
                if (trustStore != null) {
                    o.setSocketFactory(sslContext().getSocketFactory());
                }
                c.connect(o);
                return new MqttTestClient(c);
            } catch (MqttException | IOException | GeneralSecurityException e) {
                throw new IllegalStateException("test client cannot connect to " + url + ": " + e, e);
            }
        }

        private SSLContext sslContext() throws IOException, GeneralSecurityException {
            KeyStore trust = KeyStore.getInstance("PKCS12");
            try (InputStream in = Files.newInputStream(trustStore)) {
                trust.load(in, trustStorePassword.toCharArray());
            }
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(trust);
            javax.net.ssl.KeyManager[] keys = null;
            if (keyStore != null) {
                KeyStore ks = KeyStore.getInstance("PKCS12");
                try (InputStream in = Files.newInputStream(keyStore)) {
                    ks.load(in, keyStorePassword.toCharArray());
                }
                javax.net.ssl.KeyManagerFactory kmf = javax.net.ssl.KeyManagerFactory.getInstance(
                        javax.net.ssl.KeyManagerFactory.getDefaultAlgorithm());
                kmf.init(ks, keyStorePassword.toCharArray());
                keys = kmf.getKeyManagers();
            }
            SSLContext ssl = SSLContext.getInstance("TLS");
            ssl.init(keys, tmf.getTrustManagers(), null);
            return ssl;
        }
    }
}

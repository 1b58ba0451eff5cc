package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Executor;
import org.eclipse.paho.mqttv5.client.IMqttToken;
import org.eclipse.paho.mqttv5.client.MqttActionListener;
import org.eclipse.paho.mqttv5.client.MqttAsyncClient;
import org.eclipse.paho.mqttv5.client.MqttCallback;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.MqttDisconnectResponse;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttMessage;
import org.eclipse.paho.mqttv5.common.MqttSubscription;
import org.eclipse.paho.mqttv5.common.packet.MqttProperties;
import org.tinysep.json.JsonSignature;

/**
 * The connection to the broker (Eclipse Paho MQTT v5, asynchronous: nothing here blocks). Persistent session
 * ({@code cleanStart=false} with a session expiry), Last Will {@code P/F/status}=offline retained. Every Paho callback
 * is handed to the bridge's own executor; {@link Events} are called there, with the connection's generation so
 * answers of an earlier connection are told apart.
 */
final class Link {

    interface Events {
        void connected(int generation);

        void failed(int generation, String why, boolean refused);

        void lost(int generation, String why);

        void published(int generation, Message m, boolean ok);

        void command(String topic, byte[] payload);
    }

    private final Settings settings;
    private final Topics topics;
    private final Executor executor;
    private final Events events;
    private final MqttAsyncClient client;
    private volatile int generation;
    private volatile byte[] key;

    Link(Settings settings, Topics topics, Executor executor, Events events) throws MqttException {
        this.settings = settings;
        this.topics = topics;
        this.executor = executor;
        this.events = events;
        this.client = new MqttAsyncClient(settings.brokerUrl(), settings.flatId(), new MemoryPersistence());
        client.setCallback(new Callback());
    }

    /** Starts one connection attempt; the outcome comes as {@link Events#connected} or {@link Events#failed}. */
    void connect() {
        int gen = ++generation;
        MqttConnectionOptions o;
        try {
            o = options();
        } catch (IOException e) {
            executor.execute(() -> events.failed(gen, e.getMessage(), true));
            return;
        }
        try {
            client.connect(o, null, new MqttActionListener() {
                @Override
                public void onSuccess(IMqttToken token) {
                    subscribe(gen);
                }

                @Override
                public void onFailure(IMqttToken token, Throwable e) {
                    executor.execute(() -> failed(gen, e));
                }
            });
        } catch (MqttException | RuntimeException e) {
            executor.execute(() -> events.failed(gen, Trouble.connectFailure(e), Trouble.refused(e)));
        }
    }

    /** On the bridge's thread: a failure in words; for {@code ssl://} asks the broker for the TLS alert it hides. */
    private void failed(int gen, Throwable e) {
        if (settings.tls() && Trouble.mayHideTlsAlert(e)) {
            java.util.Optional<String> refusal = TlsProbe.clientCertificateRefusal(settings);
            if (refusal.isPresent()) {
                events.failed(gen, refusal.get(), true);
                return;
            }
        }
        events.failed(gen, Trouble.connectFailure(e), Trouble.refused(e));
    }

    private void subscribe(int gen) {
        MqttSubscription[] subs = {new MqttSubscription(topics.deviceCommands(), 1),
            new MqttSubscription(topics.alertAcks(), 1)};
        try {
            client.subscribe(subs, null, new MqttActionListener() {
                @Override
                public void onSuccess(IMqttToken token) {
                    executor.execute(() -> events.connected(gen));
                }

                @Override
                public void onFailure(IMqttToken token, Throwable e) {
                    executor.execute(() -> events.lost(gen, "the broker refused the command subscriptions: "
                            + Trouble.describe(e)));
                }
            }, new MqttProperties());
        } catch (MqttException | RuntimeException e) {
            executor.execute(() -> events.lost(gen, "cannot subscribe to commands: " + Trouble.describe(e)));
        }
    }

    private MqttConnectionOptions options() throws IOException {
        MqttConnectionOptions o = new MqttConnectionOptions();
        o.setCleanStart(false);
        o.setSessionExpiryInterval((long) settings.sessionExpirySeconds());
        o.setAutomaticReconnect(false);
        o.setConnectionTimeout(10);
        o.setKeepAliveInterval(30);
        MqttMessage will = new MqttMessage("offline".getBytes(StandardCharsets.UTF_8), Message.QOS, true, null);
        o.setWill(topics.status(), will);
        if (!settings.username().isEmpty()) {
            o.setUserName(settings.username());
            o.setPassword(Secrets.firstLine(settings.passwordFile(), "MQTT password").getBytes(StandardCharsets.UTF_8));
        }
        if (settings.tls()) {
            o.setSocketFactory(Tls.socketFactory(settings));
        }
        return o;
    }

    /** From now on every JSON payload is published signed with the flat's {@code key} ({@link org.tinysep.json.JsonSignature}). */
    void signWith(byte[] flatKey) {
        this.key = flatKey == null ? null : flatKey.clone();
    }

    /** Publishes with QoS 1 (a JSON payload signed, when there is a key); the outcome comes as {@link Events#published}. */
    void publish(Message m) {
        int gen = generation;
        byte[] payload = m.payload();
        byte[] k = key;
        String base = topics.status().substring(0, topics.status().length() - "status".length()); // P/F/
        if (k != null && m.topic().startsWith(base) && payload.length > 1 && payload[0] == '{'
                && payload[payload.length - 1] == '}') { // the flat's own JSON topics; discovery configs stay as they are
            payload = JsonSignature.sign(k, m.topic(), m.text()).getBytes(StandardCharsets.UTF_8);
        }
        MqttMessage msg = new MqttMessage(payload, Message.QOS, m.retained(), null);
        try {
            client.publish(m.topic(), msg, null, new MqttActionListener() {
                @Override
                public void onSuccess(IMqttToken token) {
                    executor.execute(() -> events.published(gen, m, true));
                }

                @Override
                public void onFailure(IMqttToken token, Throwable e) {
                    executor.execute(() -> events.published(gen, m, false));
                }
            });
        } catch (MqttException | RuntimeException e) {
            executor.execute(() -> events.published(gen, m, false));
        }
    }

    int generation() {
        return generation;
    }

    boolean isConnected() {
        return client.isConnected();
    }

    /**
     * Orderly stop: publishes {@code offline} (retained) and disconnects, waiting at most {@code millis} for each;
     * then releases the client. Called on the bridge's thread while it shuts down.
     */
    void close(long millis) {
        generation++;
        try {
            if (client.isConnected()) {
                client.publish(topics.status(), new MqttMessage("offline".getBytes(StandardCharsets.UTF_8),
                        Message.QOS, true, null)).waitForCompletion(millis);
                client.disconnect(millis).waitForCompletion(millis);
            }
        } catch (MqttException | RuntimeException e) {
            // the broker is gone: its Last Will says offline
        }
        try {
            client.disconnectForcibly(0, 0, false);
        } catch (MqttException | RuntimeException e) {
            // not connected
        }
        try {
            client.close(true);
        } catch (MqttException | RuntimeException e) {
            // released anyway
        }
    }

    private final class Callback implements MqttCallback {
        @Override
        public void disconnected(MqttDisconnectResponse response) {
            int gen = generation;
            String why = response.getReasonString() != null ? response.getReasonString()
                    : response.getException() != null ? Trouble.describe(response.getException()) : "the broker closed it";
            executor.execute(() -> events.lost(gen, why));
        }

        @Override
        public void mqttErrorOccurred(MqttException exception) {
            // reported through disconnected()
        }

        @Override
        public void messageArrived(String topic, MqttMessage message) {
            byte[] payload = message.getPayload();
            executor.execute(() -> events.command(topic, payload));
        }

        @Override
        public void deliveryComplete(IMqttToken token) {
            // told per message by its action listener
        }

        @Override
        public void connectComplete(boolean reconnect, String serverURI) {
            // told by the connect action listener, after the subscriptions
        }

        @Override
        public void authPacketArrived(int reasonCode, MqttProperties properties) {
            // no enhanced authentication
        }
    }
}

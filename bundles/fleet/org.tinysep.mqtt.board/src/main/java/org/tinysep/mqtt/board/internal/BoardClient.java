package org.tinysep.mqtt.board.internal;

import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.SecureRandom;
import java.time.Clock;
import java.time.Instant;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;
import org.eclipse.paho.mqttv5.client.IMqttToken;
import org.eclipse.paho.mqttv5.client.MqttAsyncClient;
import org.eclipse.paho.mqttv5.client.MqttCallback;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.MqttDisconnectResponse;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttMessage;
import org.eclipse.paho.mqttv5.common.packet.MqttProperties;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.json.JsonSignature;
import org.tinysep.json.JsonWriter;

/**
 * The board's MQTT link (Eclipse Paho v5): connects (and reconnects every {@value #RETRY_SECONDS} s while the broker
 * is away), subscribes to the flats' topics with QoS 1 on each connect (clean start: the retained topics rebuild the
 * picture), hands every message to the {@link Intake} and publishes acknowledgements. Keeps nothing on disk.
 */
final class BoardClient implements MqttCallback, AutoCloseable {

    static final int RETRY_SECONDS = 5;
    private static final Logger LOG = LoggerFactory.getLogger(BoardClient.class);
    private static final SecureRandom RANDOM = new SecureRandom();

    /** Where to connect; the passwords live only here and in ConfigAdmin. */
    record Settings(String url, String clientId, String username, char[] password, String trustStore,
            char[] trustStorePassword, String prefix) { }

    private final Settings settings;
    private final Intake intake;
    private final Clock clock;
    private final MqttAsyncClient client;
    private final ScheduledExecutorService retry = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "tinysep-board-link");
        t.setDaemon(true);
        return t;
    });
    private volatile String link;

    BoardClient(Settings settings, Intake intake, Clock clock) throws MqttException {
        this.settings = settings;
        this.intake = intake;
        this.clock = clock;
        this.client = new MqttAsyncClient(settings.url(), settings.clientId(), new MemoryPersistence());
        client.setCallback(this);
        link = "connecting to " + shown(settings.url());
    }

    void start() {
        retry.scheduleWithFixedDelay(this::connectIfNeeded, 0, RETRY_SECONDS, TimeUnit.SECONDS);
    }

    private void connectIfNeeded() {
        if (client.isConnected()) {
            return;
        }
        try {
            client.connect(options()).waitForCompletion(10_000);
        } catch (MqttException | GeneralSecurityException | IOException | RuntimeException e) {
            String words = "not connected to " + shown(settings.url()) + " (" + e.getMessage() + "); trying again every "
                    + RETRY_SECONDS + " s";
            if (!words.equals(link)) {
                LOG.warn("Central board: {}", words);
            }
            link = words;
        }
    }

    private MqttConnectionOptions options() throws GeneralSecurityException, IOException {
        MqttConnectionOptions o = new MqttConnectionOptions();
        o.setCleanStart(true);
        o.setAutomaticReconnect(false); // this class retries, also when the first connect fails
        o.setKeepAliveInterval(30);
        o.setConnectionTimeout(10);
        if (!settings.username().isEmpty()) {
            o.setUserName(settings.username());
            o.setPassword(new String(settings.password()).getBytes(StandardCharsets.UTF_8));
        }
        if (!settings.trustStore().isEmpty()) {
            KeyStore ks = KeyStore.getInstance(KeyStore.getDefaultType());
            try (InputStream in = Files.newInputStream(Path.of(settings.trustStore()))) {
                ks.load(in, settings.trustStorePassword().length == 0 ? null : settings.trustStorePassword());
            }
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(ks);
            SSLContext ssl = SSLContext.getInstance("TLS");
            ssl.init(null, tmf.getTrustManagers(), null);
            o.setSocketFactory(ssl.getSocketFactory());
        }
        return o;
    }

    @Override
    public void connectComplete(boolean reconnect, String serverURI) {
        String[] filters = Topic.filters(settings.prefix());
        int[] qos = new int[filters.length];
        Arrays.fill(qos, 1);
        try {
            client.subscribe(filters, qos);
            link = "connected to " + shown(serverURI) + " since " + now();
            LOG.info("Central board: {}, following {}/+/…", link, settings.prefix());
        } catch (MqttException e) {
            link = "connected to " + shown(serverURI) + " but the subscription failed: " + e.getMessage();
            LOG.warn("Central board: {}", link);
        }
    }

    @Override
    public void messageArrived(String topic, MqttMessage message) {
        intake.offer(topic, message.getPayload());
    }

    /** @return the time now in words ("14:02"), in the board's zone */
    private String now() {
        Instant now = Instant.now(clock);
        return BoardTime.time(now, now, clock.getZone());
    }

    @Override
    public void disconnected(MqttDisconnectResponse response) {
        link = "lost the broker " + shown(settings.url()) + " at " + now() + " ("
                + (response.getReasonString() == null ? "the connection closed" : response.getReasonString()) + "); trying again every " + RETRY_SECONDS + " s";
        LOG.warn("Central board: {}", link);
    }

    @Override
    public void mqttErrorOccurred(MqttException exception) {
        LOG.warn("Central board: MQTT error: {}", exception.getMessage());
    }

    @Override
    public void deliveryComplete(IMqttToken token) {
    }

    @Override
    public void authPacketArrived(int reasonCode, MqttProperties properties) {
    }

    /**
     * Publishes {@code {"by":…,"at":…,"nonce":…,"sig":…}} to the alert's ack topic (QoS 1), signed with the flat's
     * key (the flat carries out only signed acknowledgements, fresh and not replayed), and waits for the broker.
     */
    void acknowledge(String flat, String alertId, String by, byte[] key) throws MqttException {
        byte[] n = new byte[12];
        RANDOM.nextBytes(n);
        String topic = Topic.ack(settings.prefix(), flat, alertId);
        String body = new JsonWriter().open('{').field("by", by).field("at", Instant.now(Clock.systemUTC()).toString())
                .field("nonce", HexFormat.of().formatHex(n)).close('}').toString();
        client.publish(topic, JsonSignature.sign(key, topic, body).getBytes(StandardCharsets.UTF_8), 1, false)
                .waitForCompletion(10_000);
    }

    boolean connected() {
        return client.isConnected();
    }

    String link() {
        return link;
    }

    /** @return the URL without any user info (a password never reaches the page or the log) */
    static String shown(String url) {
        try {
            URI u = URI.create(url);
            return u.getUserInfo() == null ? url : url.replace(u.getRawUserInfo() + "@", "");
        } catch (IllegalArgumentException e) {
            return "the configured broker";
        }
    }

    @Override
    public void close() {
        retry.shutdownNow();
        try {
            retry.awaitTermination(5, TimeUnit.SECONDS);
            if (client.isConnected()) {
                client.disconnect().waitForCompletion(5_000);
            }
        } catch (MqttException e) {
            LOG.debug("Central board: disconnect: {}", e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            try {
                client.close(true);
            } catch (MqttException e) {
                LOG.debug("Central board: close: {}", e.getMessage());
            }
        }
    }
}

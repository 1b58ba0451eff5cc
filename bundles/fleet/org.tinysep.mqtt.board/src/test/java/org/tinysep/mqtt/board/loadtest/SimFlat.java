package org.tinysep.mqtt.board.loadtest;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.eclipse.paho.mqttv5.client.MqttActionListener;
import org.eclipse.paho.mqttv5.client.IMqttToken;
import org.eclipse.paho.mqttv5.client.MqttAsyncClient;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.eclipse.paho.mqttv5.common.MqttMessage;
import org.tinysep.testsupport.mqtt.Signed;

/**
 * One light simulated flat: its own MQTT connection (client id = flat id, Last Will {@code status offline}) publishing
 * what a flat's bridge publishes (see {@link Wire}) at a fixed rate, raising an alert every {@code alertSeconds}, and
 * answering the board's acknowledgement like the bridge + alert service do (ACKNOWLEDGED, then CLEARED and the
 * emptied retained topic).
 */
public final class SimFlat {

    /** Shared counters of all flats of this process. */
    static final class Stats {
        final AtomicLong published = new AtomicLong();
        final AtomicLong bytes = new AtomicLong();
        final AtomicLong boardTopics = new AtomicLong();
        final AtomicLong failed = new AtomicLong();
        final AtomicLong alerts = new AtomicLong();
        final AtomicLong acks = new AtomicLong();
    }

    record Rates(int heartbeatSeconds, int stateMillis, int alertSeconds, int occupancySeconds) { }

    private final String id;
    private final Wire wire;
    private final MqttAsyncClient client;
    private final Stats stats;
    private final Rates rates;
    private final Instant started = Instant.now();
    private final AtomicLong seq = new AtomicLong();
    private final AtomicLong alertIds = new AtomicLong();
    private boolean occupied = true;
    private boolean motion;

    SimFlat(String url, String prefix, String id, Rates rates, Stats stats) throws MqttException {
        this.id = id;
        this.wire = new Wire(prefix, id);
        this.rates = rates;
        this.stats = stats;
        this.client = new MqttAsyncClient(url, id, new MemoryPersistence());
        client.setCallback(new MessageCallback(this::acknowledge));
    }

    void start(ScheduledExecutorService ex) throws MqttException {
        MqttConnectionOptions o = new MqttConnectionOptions();
        o.setCleanStart(true);
        o.setKeepAliveInterval(60);
        o.setWill(wire.status(), new MqttMessage("offline".getBytes(StandardCharsets.UTF_8), 1, true, null));
        client.connect(o).waitForCompletion(60_000);
        client.subscribe(wire.acks(), 1).waitForCompletion(60_000);
        Instant now = Instant.now();
        send(wire.status(), "online", true, true);
        send(wire.platform(), wire.platformJson(started, now, rates.heartbeatSeconds()), true, true);
        send(wire.summary(), wire.summaryJson(now), true, true);
        send(wire.occupancy(), wire.occupancyJson(occupied, now), true, true);
        for (int d = 1; d <= 3; d++) {
            send(wire.deviceHealth(id + "-" + d), wire.healthJson(true, 3000 - d * 300, now), true, true);
        }
        ThreadLocalRandom r = ThreadLocalRandom.current();
        ex.scheduleAtFixedRate(() -> send(wire.platform(), wire.platformJson(started, Instant.now(), rates.heartbeatSeconds()), true, true),
                r.nextInt(rates.heartbeatSeconds() * 1000), rates.heartbeatSeconds() * 1000L, TimeUnit.MILLISECONDS);
        ex.scheduleAtFixedRate(this::deviceState, r.nextInt(rates.stateMillis()), rates.stateMillis(), TimeUnit.MILLISECONDS);
        ex.scheduleAtFixedRate(this::occupancy, r.nextInt(rates.occupancySeconds() * 1000), rates.occupancySeconds() * 1000L,
                TimeUnit.MILLISECONDS);
        ex.scheduleAtFixedRate(this::alert, r.nextInt(rates.alertSeconds() * 1000), rates.alertSeconds() * 1000L, TimeUnit.MILLISECONDS);
    }

    private synchronized void deviceState() {
        motion = !motion;
        send(wire.deviceState(id + "-1"), wire.deviceStateJson(id + "-1", motion, Instant.now()), true, false);
    }

    private synchronized void occupancy() {
        occupied = !occupied;
        send(wire.occupancy(), wire.occupancyJson(occupied, Instant.now()), true, true);
    }

    private void alert() {
        long alertId = alertIds.incrementAndGet();
        stats.alerts.incrementAndGet();
        send(wire.alert(alertId), wire.alertJson(alertId, "OPEN", Instant.now(), null, null, seq.incrementAndGet()), true, true);
    }

    private void acknowledge(String topic, MqttMessage message) {
        // tinysep/<flat>/command/alert/<id>/ack {"by":"…"}: the flat's alert service takes it, the bridge reports it
        String[] l = topic.split("/");
        long alertId = Long.parseLong(l[4]);
        stats.acks.incrementAndGet();
        Instant now = Instant.now();
        Instant raised = now; // the board shows the raisedAt of the OPEN message it has; not measured here
        send(wire.alert(alertId), wire.alertJson(alertId, "ACKNOWLEDGED", raised, "care centre", now, seq.incrementAndGet()), true, true);
        send(wire.alert(alertId), wire.alertJson(alertId, "CLEARED", raised, null, null, seq.incrementAndGet()), true, true);
        sendBytes(wire.alert(alertId), new byte[0], true, true);
    }

    private void send(String topic, String payload, boolean retained, boolean board) {
        sendBytes(topic, payload.getBytes(StandardCharsets.UTF_8), retained, board);
    }

    /** @return the key of flat {@code id} in the load test (the harness gives the board the same) */
    public static String key(String id) {
        return "load-test-key-of-" + id;
    }

    private void sendBytes(String topic, byte[] given, boolean retained, boolean board) {
        byte[] payload = given.length > 0 && given[0] == '{' // signed as the bridge signs its JSON (issue 25 item 2)
                ? Signed.sign(key(id), topic, new String(given, StandardCharsets.UTF_8)).getBytes(StandardCharsets.UTF_8)
                : given;
        try {
            client.publish(topic, payload, 1, retained, null, new MqttActionListener() {
                @Override
                public void onSuccess(IMqttToken token) {
                    stats.published.incrementAndGet();
                    stats.bytes.addAndGet(payload.length + topic.length());
                    if (board) {
                        stats.boardTopics.incrementAndGet();
                    }
                }

                @Override
                public void onFailure(IMqttToken token, Throwable e) {
                    stats.failed.incrementAndGet();
                }
            });
        } catch (MqttException e) {
            stats.failed.incrementAndGet();
        }
    }

    void stop() {
        try {
            client.publish(wire.status(), "offline".getBytes(StandardCharsets.UTF_8), 1, true).waitForCompletion(10_000);
            stats.boardTopics.incrementAndGet();
            stats.published.incrementAndGet();
            client.disconnect().waitForCompletion(10_000);
            client.close();
        } catch (MqttException e) {
            stats.failed.incrementAndGet();
        }
    }
}

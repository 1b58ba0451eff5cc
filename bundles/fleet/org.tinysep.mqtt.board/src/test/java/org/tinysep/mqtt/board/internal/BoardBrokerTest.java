package org.tinysep.mqtt.board.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.eclipse.paho.mqttv5.client.MqttAsyncClient;
import org.eclipse.paho.mqttv5.client.MqttConnectionOptions;
import org.eclipse.paho.mqttv5.client.persist.MemoryPersistence;
import org.eclipse.paho.mqttv5.common.MqttMessage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.json.JsonSignature;
import org.tinysep.mqtt.board.loadtest.MessageCallback;
import org.tinysep.testsupport.mqtt.Mosquitto;
import org.tinysep.testsupport.mqtt.Signed;

/**
 * The board on Debian's real Mosquitto: a flat (a plain Paho client publishing exactly the contract's messages)
 * raises an alert, the board shows it, the board's acknowledgement travels to the flat, the flat's ACKNOWLEDGED
 * comes back and the board shows it confirmed; the flat's link dies and its Last Will makes it offline.
 */
class BoardBrokerTest {

    static final Duration LIMIT = Duration.ofSeconds(60);
    static final String KEY = "flat-17-key-0123456789abcdef";

    @TempDir
    Path var;
    final List<String> problems = new CopyOnWriteArrayList<>();

    @Test
    void alertTravelsToTheBoardAndItsAcknowledgementBackToTheFlat() throws Exception {
        assumeTrue(Mosquitto.isInstalled(), "Debian's mosquitto is not installed (scripts/install-deps.sh)");
        Path passwordFile = Files.writeString(var.resolve("board.password"), "b0ard-pass\n");
        Path keyFile = Files.writeString(Files.createDirectories(var.resolve("secrets/flats")).resolve("17.key"), KEY);
        Files.setPosixFilePermissions(keyFile, PosixFilePermissions.fromString("rw-------"));
        Files.setPosixFilePermissions(passwordFile, PosixFilePermissions.fromString("rw-------"));
        try (Mosquitto broker = Mosquitto.builder().user("care", "b0ard-pass").start();
                Central central = new Central(Configs.board(Map.of("brokerUrl", broker.url(), "username", "care",
                        "passwordFile", passwordFile.toString())), Clock.systemUTC(), null, var, problems::add)) {
            MqttAsyncClient flat = new MqttAsyncClient(broker.url(), "17", new MemoryPersistence());
            MqttConnectionOptions o = new MqttConnectionOptions();
            o.setUserName("care"); // the test support makes one user
            o.setPassword("b0ard-pass".getBytes(StandardCharsets.UTF_8));
            o.setWill("tinysep/17/status", new MqttMessage("offline".getBytes(StandardCharsets.UTF_8), 1, true, null));
            BlockingQueue<String> acks = new LinkedBlockingQueue<>(); // every message as "topic payload"
            flat.setCallback(new MessageCallback((topic, m) -> acks.add(topic + " "
                    + new String(m.getPayload(), StandardCharsets.UTF_8))));
            flat.connect(o).waitForCompletion(20_000);
            flat.subscribe("tinysep/17/command/alert/+/ack", 1).waitForCompletion(20_000);

            publish(flat, "tinysep/17/status", "online");
            // started now: a fixed start date would make the flat SILENT (no daily summary for 26 h) from a day after it
            signed(flat, "tinysep/17/platform", BoardTest.platform(Instant.now(), Instant.now()));
            signed(flat, "tinysep/17/alert/3", BoardTest.alert(3, "OPEN", 1));
            Conditions.await("the board to show flat 17's open alert", LIMIT,
                    () -> central.json().contains("\"state\":\"OPEN\"") && central.json().contains("\"status\":\"ONLINE\""),
                    central::json);

            // another client on the broker (issue 25 item 2): an unsigned retained CLEARED with a huge seq, then the
            // empty retained message that would delete the alert, then a fake flat with a fake alert: none counts
            MqttAsyncClient other = new MqttAsyncClient(broker.url(), "intruder", new MemoryPersistence());
            other.connect(o).waitForCompletion(20_000);
            publish(other, "tinysep/17/alert/3", BoardTest.alert(3, "CLEARED", 999_999));
            publish(other, "tinysep/17/alert/3", "");
            publish(other, "tinysep/flat-evil/status", "online");
            publish(other, "tinysep/flat-evil/alert/1", BoardTest.alert(1, "OPEN", 1).replace("\"17\"", "\"flat-evil\""));
            Conditions.await("the board to have seen the intruder's messages", LIMIT,
                    () -> central.json().contains("\"unknownFlats\":2,\"unsigned\":2"), central::json);
            assertTrue(central.json().contains("\"state\":\"OPEN\""), central.json());
            assertTrue(!central.json().contains("flat-evil"), central.json());
            other.disconnect().waitForCompletion(5_000);
            other.close();

            String words = central.acknowledge("17", "3", "Eva");
            assertTrue(words.startsWith("acknowledgement of alert 3 sent to flat 17 by Eva"), words);
            String ack = acks.poll(60, TimeUnit.SECONDS);
            assertTrue(ack.startsWith("tinysep/17/command/alert/3/ack {\"by\":\"Eva\",\"at\":\""), ack);
            String payload = ack.substring(ack.indexOf(' ') + 1);
            assertTrue(JsonSignature.check(KEY.getBytes(StandardCharsets.UTF_8), "tinysep/17/command/alert/3/ack", payload)
                    .valid(), "the acknowledgement signed with flat 17's key: " + payload);
            assertTrue(payload.contains("\"nonce\":\""), payload);
            assertTrue(central.json().contains("acknowledgement sent by Eva at "), central.json());

            signed(flat, "tinysep/17/alert/3", BoardTest.alert(3, "ACKNOWLEDGED", 2)); // the flat confirms
            Conditions.await("the board to show the flat's confirmation", LIMIT,
                    () -> central.json().contains("acknowledged by Eva at ") // "14:05" the day of the fixture, else with its date
                            && central.json().contains("; the flat confirmed it at "), central::json);

            flat.disconnectForcibly(0, 1000, false); // the link dies without a DISCONNECT: the broker sends the will
            Conditions.await("flat 17 offline by its Last Will", LIMIT,
                    () -> central.json().contains("\"status\":\"OFFLINE\"") && central.json().contains("Last Will"), central::json);
            assertTrue(central.json().contains("\"connected\":true"), central.json());
            assertTrue(!central.json().contains("b0ard-pass"), "the password never reaches the page");
            assertEquals(List.of(), problems, "a login from an owner-only file: nothing to warn about");
            flat.close(true);
        }
    }

    @Test
    void idleWithoutABrokerAndSaysSo() throws Exception {
        try (Central central = new Central(Configs.board(Map.of()), Clock.systemUTC(), null, var, problems::add)) {
            assertTrue(central.json().contains("idle: no broker configured"), central.json());
        }
    }

    static void signed(MqttAsyncClient client, String topic, String json) throws Exception {
        publish(client, topic, Signed.sign(KEY, topic, json));
    }

    static void publish(MqttAsyncClient client, String topic, String payload) throws Exception {
        client.publish(topic, payload.getBytes(StandardCharsets.UTF_8), 1, true).waitForCompletion(20_000);
    }
}

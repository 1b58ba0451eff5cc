package org.tinysep.itests.mqtt;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.time.Instant;
import java.util.HashMap;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.itests.AmicaNode;
import org.tinysep.testsupport.mqtt.Mosquitto;
import org.tinysep.testsupport.mqtt.MqttTestClient;
import org.tinysep.testsupport.mqtt.Signed;

/**
 * The MQTT bridge (issue 15) against a real Mosquitto broker (Debian's binary on a free port of 127.0.0.1): real
 * AmICA nodes over UDP, the real alert service, a recording MQTT client on the other side.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class MqttBridgeTest extends MqttBridgeSupport {

    static final String PID = "org.tinysep.mqtt";
    static final String FLAT = "flat1";
    static final String BASE = "tinysep/" + FLAT + "/";
    static final Duration WAIT = Duration.ofSeconds(30);
    /** The flat's key (keyFile): the care centre signs its commands with it (issue 25 item 2). */
    static final String KEY = "flat1-key-0123456789abcdef";
    private static final Pattern SEQ = Pattern.compile("\"seq\":(\\d+)");

    private Map<String, String> bridge(Mosquitto broker) throws Exception {
        Map<String, String> c = new HashMap<>();
        c.put("brokerUrl", broker.url());
        c.put("flatId", FLAT);
        c.put("queueDir", Files.createTempDirectory("tinysep-mqtt-outbox").toString());
        c.put("allowAnonymous", "true"); // the test broker lets anyone in (issue 25 item 2: only with the override)
        Path key = Files.createTempDirectory("tinysep-mqtt-key").resolve("mqtt.key");
        Files.writeString(key, KEY + "\n", StandardCharsets.UTF_8);
        Files.setPosixFilePermissions(key, PosixFilePermissions.fromString("rw-------"));
        c.put("keyFile", key.toString());
        return c;
    }

    private Device bridgeDevice() {
        return awaitService(Device.class, "(tinysep.driver.name=MqttBridge)", TIMEOUT);
    }

    private static String parameter(Device d, String key) {
        return d.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow(() -> new AssertionError("no parameter " + key + " in " + d.parameters()));
    }

    private static String uidOf(MqttTestClient.Received state) {
        return state.topic().substring(BASE.length() + "device/".length(), state.topic().length() - "/state".length());
    }

    private static long seqOf(MqttTestClient.Received r) {
        Matcher m = SEQ.matcher(r.payload());
        assertTrue("a seq in " + r.payload(), m.find());
        return Long.parseLong(m.group(1));
    }

    @Test
    public void idleUntilABrokerIsConfigured() {
        Device d = bridgeDevice();
        await(TIMEOUT, () -> d.status().detail().contains("idle"), "the bridge idle: " + d.status());
        assertEquals("none", parameter(d, "broker"));
    }

    @Test
    public void withoutALoginTheBridgeDoesNotConnectUnlessAnonymousIsAllowed() throws Exception {
        try (Mosquitto broker = Mosquitto.startDefault();
                MqttTestClient sub = MqttTestClient.connect(broker.url(), "observer").subscribe(BASE + "status")) {
            Map<String, String> c = bridge(broker);
            c.remove("allowAnonymous");
            configure(PID, c);
            Device d = bridgeDevice();
            await(TIMEOUT, () -> d.status().detail().contains("no broker login is configured"), "refused: " + d.status());
            assertEquals(DeviceStatus.State.ERROR, d.status().state());
            EventLog log = awaitService(EventLog.class, null, TIMEOUT);
            await(TIMEOUT, () -> log.recent(200).stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                    && e.message().startsWith("Monitoring reduced: the MQTT bridge of flat " + FLAT)), "the PROBLEM");
            Thread.sleep(1500); // a connection attempt would have reached the broker by now
            assertTrue(sub.received(BASE + "status").toString(), sub.received(BASE + "status").isEmpty());
            assertTrue(broker.log(), !broker.log().contains(" as " + FLAT + " "));

            configure(PID, bridge(broker)); // with the override: it connects, and says loudly what that means
            sub.await(BASE + "status", "online", WAIT);
            await(TIMEOUT, () -> log.recent(200).stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                    && e.message().contains("WITHOUT a login (allowAnonymous=true): anyone")), "the warning");
        }
    }

    @Test
    public void stateDiscoveryAndCommandsRoundTrip() throws Exception {
        try (Mosquitto broker = Mosquitto.startDefault();
                MqttTestClient sub = MqttTestClient.connect(broker.url(), "observer").subscribe(BASE + "#",
                        "homeassistant/#");
                AmicaNode motion = new AmicaNode(1, 10, udpPortOf("BusRadioAmicaUdp"), AmicaNodeType.MOVEMENT);
                AmicaNode light = new AmicaNode(1, 20, udpPortOf("BusRadioAmicaUdp"), AmicaNodeType.SIMPLE_LIGHT)) {
            Map<String, String> config = bridge(broker);
            config.put("commands.actuators", "signed");
            configure(PID, config);
            sub.await(BASE + "status", "online", WAIT);

            // a sensor: its state and its Home Assistant entity
            motion.keepAlive();
            motion.motion(true);
            MqttTestClient.Received m = sub.await("a movement state with value true", WAIT,
                    r -> r.topic().endsWith("/state") && r.payload().contains("\"type\":\"movement\"")
                            && r.payload().contains("\"value\":true"));
            assertTrue(m.retained() || m.payload().contains("explanation"));
            String motionUid = uidOf(m);
            MqttTestClient.Received motionConfig = sub.await("homeassistant/binary_sensor/tinysep_flat1_" + motionUid
                    + "/config", "\"device_class\":\"motion\"", WAIT);
            assertTrue(motionConfig.payload(), motionConfig.payload().contains("\"unique_id\":\"tinysep_flat1_"
                    + motionUid + "\""));
            assertTrue(motionConfig.payload(), motionConfig.payload().contains(BASE + "device/" + motionUid
                    + "/availability"));
            assertTrue(motionConfig.payload(), motionConfig.payload().contains("\"identifiers\":[\"tinysep_flat1_"
                    + motionUid + "\"]"));
            sub.await(BASE + "device/" + motionUid + "/availability", "online", WAIT);
            sub.await(BASE + "device/" + motionUid + "/health", "\"status\"", WAIT);
            sub.await("homeassistant/binary_sensor/tinysep_flat1_alert_inactivity/config", "\"device_class\":\"problem\"",
                    WAIT);
            sub.await("homeassistant/binary_sensor/tinysep_flat1_occupancy/config", "occupancy", WAIT);
            sub.await(BASE + "occupancy", "\"state\":\"OCCUPIED\"", WAIT);
            sub.await(BASE + "platform", "\"heartbeatSeconds\":60", WAIT);
            MqttTestClient.Received drivers = sub.await(BASE + "drivers", " in the drivers list, ", WAIT);
            assertTrue(drivers.payload(), drivers.payload().contains("\"applications\":[")); // live: retain flag not kept

            // an actuator: state, entity with a command topic, a command that reaches the node
            light.keepAlive();
            light.send(new LightControl(0));
            MqttTestClient.Received l = sub.await("a light state with value false", WAIT,
                    r -> r.topic().endsWith("/state") && r.payload().contains("\"type\":\"light\"")
                            && r.payload().contains("\"value\":false"));
            String lightUid = uidOf(l);
            sub.await("homeassistant/light/tinysep_flat1_" + lightUid + "/config",
                    "\"command_topic\":\"" + BASE + "command/device/" + lightUid + "\"", WAIT);
            String lightTopic = BASE + "command/device/" + lightUid;
            // anyone on the broker (issue 25 item 2): an unsigned command is refused, the light is not switched
            sub.publish(lightTopic, "{\"parameter\":\"on\",\"value\":true}", false);
            sub.await(BASE + "command/result", "unsigned command refused", WAIT);
            AssertionError nothing = org.junit.Assert.assertThrows(AssertionError.class, light::receivePayload);
            assertTrue(nothing.getMessage(), nothing.getMessage().contains("received no frame"));
            // signed with the flat's key, fresh and with a new nonce: carried out
            sub.publish(lightTopic, Signed.command(KEY, lightTopic, "\"parameter\":\"on\",\"value\":true"), false);
            assertEquals(new LightControl(100), AmicaPayloads.decode(light.receivePayload()));
            sub.await(BASE + "command/result", "\"accepted\":true", WAIT);
            light.send(new LightControl(100));
            sub.await("the light on", WAIT, r -> r.topic().equals(BASE + "device/" + lightUid + "/state")
                    && r.payload().contains("\"value\":true"));

            // bad commands: refused in words and counted, the bridge goes on
            sub.publish(lightTopic, Signed.command(KEY, lightTopic, "\"parameter\":\"on\",\"value\":\"maybe\""), false);
            sub.await(BASE + "command/result", "cannot set on on " + lightUid, WAIT);
            sub.publish(lightTopic, "not json", false);
            sub.await(BASE + "command/result", "unsigned command refused", WAIT);
            String motionTopic = BASE + "command/device/" + motionUid;
            sub.publish(motionTopic, Signed.command(KEY, motionTopic, "\"parameter\":\"on\",\"value\":true"), false);
            sub.await(BASE + "command/result", "only lights, heaters and speakers take commands", WAIT);
            sub.publish(lightTopic, Signed.command(KEY, lightTopic, "\"parameter\":\"room\",\"value\":\"Attic\""), false);
            sub.await(BASE + "command/result", "only 'on' can be set over MQTT", WAIT);
            Device d = bridgeDevice();
            await(TIMEOUT, () -> "5".equals(parameter(d, "rejectedCommands")), "5 rejected commands, was "
                    + parameter(d, "rejectedCommands"));
            assertEquals("1", parameter(d, "acceptedCommands"));
            assertEquals("2", parameter(d, "refusedCommandsUnauthorised"));

            // and a signed OFF still works afterwards
            sub.publish(lightTopic, Signed.command(KEY, lightTopic, "\"parameter\":\"on\",\"value\":false"), false);
            assertEquals(new LightControl(0), AmicaPayloads.decode(light.receivePayload()));
        }
    }

    @Test
    public void alertRaisedWhileTheBrokerIsDownArrivesOnceItIsBack() throws Exception {
        try (Mosquitto broker = Mosquitto.startDefault()) {
            configure(PID, bridge(broker));
            AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
            Device d = bridgeDevice();
            long before;
            try (MqttTestClient sub = MqttTestClient.connect(broker.url(), "board").subscribe(BASE + "alert/+")) {
                Alert first = alerts.raise(request("mqtt-test-1"));
                MqttTestClient.Received r = sub.await(BASE + "alert/" + first.id(), "\"state\":\"OPEN\"", WAIT);
                before = seqOf(r);
            }
            broker.stop();
            await(TIMEOUT, () -> d.status().state() == DeviceStatus.State.OFFLINE, "the bridge offline: "
                    + d.status());
            Alert second = alerts.raise(request("mqtt-test-2"));
            await(TIMEOUT, () -> "1".equals(parameter(d, "waitingAlerts")), "the alert waiting on disk, was "
                    + parameter(d, "waitingAlerts"));
            broker.start();
            try (MqttTestClient sub = MqttTestClient.connect(broker.url(), "board").subscribe(BASE + "alert/+", BASE + "command/result")) {
                String topic = BASE + "alert/" + second.id();
                MqttTestClient.Received open = sub.await(topic, "\"state\":\"OPEN\"", WAIT);
                assertTrue("seq " + seqOf(open) + " after " + before, seqOf(open) > before);
                await(TIMEOUT, () -> "0".equals(parameter(d, "waitingAlerts")), "the outbox empty");
                assertTrue(open.payload(), open.payload().matches(".*,\"sig\":\"[0-9a-f]{64}\"\\}"));
                // anyone on the broker (issue 25 item 2): an unsigned acknowledgement is refused, the alert stays open
                String ack = BASE + "command/alert/" + second.id() + "/ack";
                sub.publish(ack, "{\"by\":\"Mallory\"}", false);
                sub.await(BASE + "command/result", "unsigned command refused", WAIT);
                assertEquals(AlertState.OPEN, alerts.alert(second.id()).orElseThrow().state());
                // acknowledged from the board, signed: a later message on the same topic is the barrier for duplicates
                sub.publish(ack, Signed.command(KEY, ack, "\"by\":\"Anna (care centre)\""), false);
                MqttTestClient.Received acked = sub.await(topic, "\"state\":\"ACKNOWLEDGED\"", WAIT);
                assertTrue(acked.payload(), acked.payload().contains("\"acknowledgedBy\":\"Anna (care centre)\""));
                assertTrue(seqOf(acked) > seqOf(open));
                assertEquals("Anna (care centre)", alerts.alert(second.id()).orElseThrow().closedBy());
                long opens = sub.received(topic).stream().filter(x -> x.payload().contains("\"state\":\"OPEN\""))
                        .count();
                assertEquals("the OPEN message exactly once: " + sub.received(topic), 1, opens);
                // cleared: CLEARED, then the retained topic emptied
                alerts.clear("mqtt-test-2", "movement in the kitchen");
                sub.await(topic, "\"state\":\"CLEARED\"", WAIT);
                sub.await("the emptied retained alert", WAIT, x -> x.topic().equals(topic) && x.payload().isEmpty());
            }
        }
    }

    @Test
    public void tlsAndPasswordFile() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().tls(true).user(FLAT, "s3cret word").start()) {
            Path password = Files.createTempDirectory("tinysep-mqtt-secret").resolve("mqtt.password");
            Files.writeString(password, "wrong\n", StandardCharsets.UTF_8);
            Files.setPosixFilePermissions(password, PosixFilePermissions.fromString("rw-------"));
            Map<String, String> c = bridge(broker);
            c.put("username", FLAT);
            c.put("passwordFile", password.toString());
            c.put("trustStore", broker.trustStore().toString());
            c.put("trustStorePassword", Mosquitto.TRUST_STORE_PASSWORD);
            configure(PID, c);
            Device d = bridgeDevice();
            await(TIMEOUT, () -> d.status().state() == DeviceStatus.State.ERROR
                    && d.status().detail().contains("the broker refused the login"), "the login refused in words");
            Files.writeString(password, "s3cret word\n", StandardCharsets.UTF_8);
            c.put("heartbeatSeconds", "30"); // a changed configuration restarts the bridge at once
            configure(PID, c);
            try (MqttTestClient sub = MqttTestClient.builder(broker.url()).user(FLAT, "s3cret word")
                    .trustStore(broker.trustStore(), Mosquitto.TRUST_STORE_PASSWORD).connect()
                    .subscribe(BASE + "status", BASE + "platform")) {
                sub.await(BASE + "status", "online", WAIT);
                sub.await(BASE + "platform", "\"heartbeatSeconds\":30", WAIT);
            }
            await(TIMEOUT, () -> d.status().state() == DeviceStatus.State.ONLINE, "online: " + d.status());
        }
    }

    private static AlertRequest request(String source) {
        return new AlertRequest(AlertKind.INACTIVITY, source, "", "Bathroom", Instant.now(),
                "TinySEP: no activity in Bathroom (" + source + ")", "A test alert from " + source + ".");
    }
}

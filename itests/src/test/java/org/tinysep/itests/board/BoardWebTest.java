package org.tinysep.itests.board;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;
import static org.ops4j.pax.exam.CoreOptions.frameworkProperty;

import java.io.IOException;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.Option;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.itests.web.WebTestSupport;

/**
 * The central alert board bundle in the framework with the web console, on Debian's real Mosquitto (a process on
 * a free port of 127.0.0.1): a flat (a raw MQTT client publishing the contract's messages) raises an alert, the
 * board's JSON shows it behind the console's login, the caregiver's acknowledgement reaches the flat, the flat's
 * ACKNOWLEDGED comes back. Also: the page is behind the login; the caregiver may acknowledge (with the CSRF header).
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class BoardWebTest extends WebTestSupport {

    private static final String PORT = "tinysep.test.mqtt.port";
    private static int brokerPort;

    private static synchronized int brokerPort() {
        if (brokerPort == 0) {
            brokerPort = freePortHere();
        }
        return brokerPort;
    }

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.add(frameworkProperty(PORT).value(Integer.toString(brokerPort())));
        o.add(reactorBundle("org.tinysep.mqtt.board", 5));
        return o;
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.mqtt.board", Map.of("brokerUrl", "tcp://127.0.0.1:" + brokerPort(), "clientId", "itest-board",
                "allowAnonymous", "true", "flatKeyDir", KEYS.toString()));
        return configs;
    }

    @Test
    public void aFlatsAlertOnTheBoardAndItsAcknowledgementBack() throws Exception {
        Path mosquitto = Path.of("/usr/sbin/mosquitto");
        assumeTrue("Debian's mosquitto is not installed (scripts/install-deps.sh)", Files.isExecutable(mosquitto));
        setPasswords();
        Login caregiver = login("caregiver", CAREGIVER_PASSWORD);
        Login installer = login("installer", INSTALLER_PASSWORD);
        assertEquals(302, call("GET", "/board/", null, null, false).statusCode());
        HttpResponse<String> page = call("GET", "/board/", null, caregiver, false);
        assertEquals(200, page.statusCode());
        assertTrue(page.body(), page.body().contains("Central alert board"));

        int port = Integer.parseInt(context.getProperty(PORT));
        Path dir = Files.createTempDirectory("tinysep-board-itest-");
        Files.writeString(dir.resolve("mosquitto.conf"), "listener " + port + " 127.0.0.1\nallow_anonymous true\n"
                + "persistence false\nlog_dest file " + dir.resolve("mosquitto.log") + "\n");
        Process broker = new ProcessBuilder(mosquitto.toString(), "-c", dir.resolve("mosquitto.conf").toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("out.txt").toFile()).start();
        try {
            RawMqtt flat = connect(port);
            flat.subscribe("tinysep/17/command/alert/+/ack");
            flat.publish("tinysep/17/status", "online", true);
            flat.publish("tinysep/17/platform", signed("tinysep/17/platform", "{\"flat\":\"17\",\"version\":\"0.1.0\",\"heartbeatAt\":\"" + Instant.now()
                    + "\",\"heartbeatSeconds\":60}"), true);
            flat.publish("tinysep/17/alert/5", signed("tinysep/17/alert/5", alert("OPEN", 1)), true);
            await(Duration.ofSeconds(60), () -> board(caregiver).contains("\"state\":\"OPEN\""), "flat 17's open alert on the board");
            String json = board(caregiver);
            assertTrue(json, json.contains("\"connected\":true") && json.contains("\"status\":\"ONLINE\"")
                    && json.contains("Flat 17: online since"));

            String ack = "/board/api/flats/17/alerts/5/acknowledge";
            assertEquals("without the CSRF header even the acknowledgement is refused", 403,
                    call("POST", ack, "{\"by\":\"Eva\"}", caregiver, false).statusCode());
            HttpResponse<String> done = call("POST", ack, "{\"by\":\"Eva\"}", caregiver, true);
            assertEquals("the caregiver may acknowledge on the board: " + done.body(), 200, done.statusCode());
            String sent = flat.next();
            assertTrue(sent, sent.startsWith("tinysep/17/command/alert/5/ack {\"by\":\"Eva\",\"at\":\"")
                    && sent.matches(".*,\"sig\":\"[0-9a-f]{64}\"\\}"));
            flat.publish("tinysep/17/alert/5", signed("tinysep/17/alert/5", alert("ACKNOWLEDGED", 2)), true);
            await(Duration.ofSeconds(60), () -> board(caregiver).contains("the flat confirmed it at"), "the flat's confirmation");
            assertEquals(409, call("POST", ack, null, installer, true).statusCode());
            flat.close();
        } finally {
            broker.destroy();
            broker.waitFor();
        }
    }

    private String board(Login login) {
        return call("GET", "/board/api/flats", null, login, false).body();
    }

    private RawMqtt connect(int port) throws InterruptedException {
        long end = System.nanoTime() + Duration.ofSeconds(30).toNanos();
        while (true) {
            try {
                return new RawMqtt(port, "17");
            } catch (IOException e) {
                if (System.nanoTime() > end) {
                    throw new AssertionError("mosquitto did not start on port " + port + ": " + e.getMessage());
                }
                Thread.sleep(100);
            }
        }
    }

    static final String KEY = "flat-17-key-0123456789abcdef";
    /** The board's flatKeyDir with 17.key: one fixed place (the driver and the probe each load this class). */
    static final Path KEYS = Path.of(System.getProperty("java.io.tmpdir"), "tinysep-boardweb-keys");

    static {
        try {
            Files.createDirectories(KEYS);
            Files.writeString(KEYS.resolve("17.key"), KEY + "\n");
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** @return {@code json} signed as flat 17's bridge signs (docs/mqtt.md, "Signed messages") */
    private static String signed(String topic, String json) {
        try {
            javax.crypto.Mac mac = javax.crypto.Mac.getInstance("HmacSHA256");
            mac.init(new javax.crypto.spec.SecretKeySpec(KEY.getBytes(java.nio.charset.StandardCharsets.UTF_8), "HmacSHA256"));
            String sig = java.util.HexFormat.of().formatHex(mac.doFinal((topic + "\n" + json)
                    .getBytes(java.nio.charset.StandardCharsets.UTF_8)));
            return json.substring(0, json.length() - 1) + ",\"sig\":\"" + sig + "\"}";
        } catch (java.security.GeneralSecurityException e) {
            throw new IllegalStateException(e);
        }
    }

    private static String alert(String state, long seq) {
        boolean acked = state.equals("ACKNOWLEDGED");
        return "{\"id\":\"5\",\"flat\":\"17\",\"kind\":\"INACTIVITY\",\"state\":\"" + state + "\",\"raisedAt\":\"" + Instant.now()
                + "\",\"room\":\"Bedroom\",\"title\":\"No activity\",\"text\":\"No movement for 2 h\",\"acknowledgedBy\":"
                + (acked ? "\"Eva\"" : "null") + ",\"acknowledgedAt\":" + (acked ? "\"" + Instant.now() + "\"" : "null")
                + ",\"seq\":" + seq + "}";
    }

    private static int freePortHere() {
        try (java.net.ServerSocket s = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}

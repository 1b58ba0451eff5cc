package org.tinysep.itests.mqtt;

import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashMap;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.testsupport.mqtt.ClientCertificates;
import org.tinysep.testsupport.mqtt.Mosquitto;
import org.tinysep.testsupport.mqtt.MqttTestClient;

/**
 * The MQTT bridge in the framework against Debian's Mosquitto requiring client certificates
 * ({@code require_certificate true}, a client CA of its own). Certificates are made in the test with openssl
 * ({@link ClientCertificates}): with the flat's certificate the bridge connects (its device ONLINE, {@code status}
 * online seen by a subscriber that has a certificate too); with a self-signed certificate and with none, it is refused
 * and its device says why in plain words (ERROR, one line, no exception name).
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class MqttClientCertificateTest extends MqttBridgeSupport {

    private static final String PID = "org.tinysep.mqtt";
    private static final String PASSWORD = "flat-key-password";
    private static final Duration WAIT = Duration.ofSeconds(60);

    @Test
    public void connectsWithItsCertificateAndIsRefusedInWordsWithoutOrWithAnUntrustedOne() throws Exception {
        try (Mosquitto broker = Mosquitto.builder().requireClientCertificate(true).start()) {
            Path certs = Files.createTempDirectory("tinysep-mqtt-certs");
            Path flat = ClientCertificates.issue(broker, certs, "flat1", PASSWORD);
            Path board = ClientCertificates.issue(broker, certs, "board", PASSWORD);
            Path stranger = ClientCertificates.selfSigned(certs.resolve("stranger"), "flat1", PASSWORD);
            Path passwordFile = certs.resolve("key.password");
            Files.writeString(passwordFile, PASSWORD + "\n", StandardCharsets.UTF_8);

            Map<String, String> c = new HashMap<>();
            c.put("brokerUrl", broker.url());
            c.put("flatId", "flat1");
            c.put("queueDir", Files.createTempDirectory("tinysep-mqtt-outbox").toString());
            c.put("trustStore", broker.trustStore().toString());
            c.put("trustStorePassword", Mosquitto.TRUST_STORE_PASSWORD);
            c.put("keyStore", flat.toString());
            c.put("keyStorePasswordFile", passwordFile.toString());
            configure(PID, c);
            Device d = awaitService(Device.class, "(tinysep.driver.name=MqttBridge)", TIMEOUT);
            try (MqttTestClient sub = MqttTestClient.builder(broker.url())
                    .trustStore(broker.trustStore(), Mosquitto.TRUST_STORE_PASSWORD).keyStore(board, PASSWORD).connect()
                    .subscribe("tinysep/flat1/status")) {
                sub.await("tinysep/flat1/status", "online", WAIT);
            }
            await(WAIT, () -> d.status().state() == DeviceStatus.State.ONLINE, "online with its certificate: " + d.status());

            c.put("keyStore", stranger.toString());
            configure(PID, c);
            await(WAIT, () -> d.status().state() == DeviceStatus.State.ERROR
                    && d.status().detail().contains("the broker refused this flat's client certificate"),
                    "the self-signed certificate refused in words: " + d.status());
            plainWords(d.status().detail());

            c.remove("keyStore");
            c.remove("keyStorePasswordFile");
            configure(PID, c);
            // no login of its own: the bridge does not even try (issue 25, item 2) ...
            await(WAIT, () -> d.status().state() == DeviceStatus.State.ERROR
                    && d.status().detail().contains("no broker login is configured"),
                    "no login refused by the bridge itself: " + d.status());
            plainWords(d.status().detail());
            // ... and told it may (allowAnonymous), it is refused by the broker, in words
            c.put("allowAnonymous", "true");
            configure(PID, c);
            await(WAIT, () -> d.status().state() == DeviceStatus.State.ERROR
                    && d.status().detail().contains("the broker requires a client certificate"),
                    "no certificate refused in words: " + d.status());
            plainWords(d.status().detail());
            log.info("Bridge without a client certificate: {}", d.status());
        }
    }

    private static void plainWords(String detail) {
        assertTrue(detail, !detail.contains("\n") && !detail.contains("Exception") && !detail.contains("\tat "));
    }
}

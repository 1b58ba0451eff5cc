package org.tinysep.itests.board;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.itests.mqtt.MqttBridgeSupport;
import org.tinysep.testsupport.mqtt.Mosquitto;

/**
 * The whole way, with real parts only: the alert service raises an alert, the real MQTT bridge (org.tinysep.mqtt)
 * publishes it to Debian's Mosquitto, the central board shows it (its JSON behind the console's login), the
 * installer acknowledges it on the board, the acknowledgement travels to the bridge, the alert service records who
 * took care of it, and the board shows the flat's confirmation. Then the bridge stops and the board says the flat
 * is offline. (Board and bridge run in one framework here, as a flat's TinySEP showing its own board may.)
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class BoardBridgeTest extends MqttBridgeSupport {

    static final Duration WAIT = Duration.ofSeconds(60);

    @Test
    public void theBridgesAlertOnTheBoardAndItsAcknowledgementBackToTheAlertService() throws Exception {
        setPasswords();
        Login installer = login("installer", INSTALLER_PASSWORD);
        try (Mosquitto broker = Mosquitto.startDefault()) {
            Path keys = flatKeyDir("flat1", "flat1-key-0123456789abcdef"); // the flat signs, the board checks
            configure("org.tinysep.mqtt", Map.of("brokerUrl", broker.url(), "flatId", "flat1",
                    "queueDir", Files.createTempDirectory("tinysep-board-outbox").toString(), "allowAnonymous", "true",
                    "keyFile", keys.resolve("flat1.key").toString()));
            configure("org.tinysep.mqtt.board", Map.of("brokerUrl", broker.url(), "clientId", "care-board",
                    "allowAnonymous", "true", "flatKeyDir", keys.toString()));
            await(WAIT, () -> board(installer).contains("Flat flat1: online since"), "flat1 online on the board");

            AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
            Alert a = alerts.raise(new AlertRequest(AlertKind.INACTIVITY, "board-test", "", "Bathroom", Instant.now(),
                    "TinySEP: no activity in Bathroom since 13:15", "Inactivity Recognition raised an alert."));
            java.util.regex.Pattern open = java.util.regex.Pattern.compile("\"id\":\"" + a.id()
                    + "\",\"kind\":\"INACTIVITY\",\"kindWords\":\"[^\"]+\",\"state\":\"OPEN\""); // kind also in words
            await(WAIT, () -> open.matcher(board(installer)).find(), "alert " + a.id() + " open on the board");

            HttpResponse<String> done = call("POST", "/board/api/flats/flat1/alerts/" + a.id() + "/acknowledge",
                    "{\"by\":\"Eva (care centre)\"}", installer, true);
            assertEquals(done.body(), 200, done.statusCode());
            await(WAIT, () -> alerts.alert(a.id()).orElseThrow().state() == AlertState.ACKNOWLEDGED,
                    "the flat's alert service to take the acknowledgement");
            assertEquals("Eva (care centre)", alerts.alert(a.id()).orElseThrow().closedBy());
            await(WAIT, () -> board(installer).contains("acknowledged by Eva (care centre) at "), "the flat's confirmation");
            assertTrue(board(installer), board(installer).contains("the flat confirmed it at"));

            configure("org.tinysep.mqtt", Map.of("brokerUrl", "", "flatId", "flat1")); // the flat's bridge stops
            await(WAIT, () -> board(installer).contains("Flat flat1: platform offline since"), "flat1 offline on the board");
        }
    }

    private String board(Login login) {
        return call("GET", "/board/api/flats", null, login, false).body();
    }
}

package org.tinysep.itests.board;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

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
import org.tinysep.itests.web.Chromium;
import org.tinysep.itests.mqtt.MqttBridgeSupport;
import org.tinysep.testsupport.mqtt.Mosquitto;

/**
 * The central alert board in a real browser (Debian's headless Chromium over the DevTools protocol), with real parts
 * only: the caregiver logs in through the console's form, the board at {@code /board/} lists the flat (online, in
 * plain words), the alert service raises an alert that the real MQTT bridge publishes to Debian's Mosquitto and the
 * board shows it in plain words with its Acknowledge button; the caregiver clicks it (the page's name prompt is
 * answered by replacing {@code window.prompt}: a DevTools dialog would block the click's evaluation), the
 * acknowledgement travels through the broker to the flat, whose alert service records who took care of it, and the
 * page shows the flat's confirmation. Screenshot: {@code target/web-screenshots/board.png}; on failure
 * {@code failure-board.png}. Every step waits on a condition, never a fixed time.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class BoardBrowserTest extends MqttBridgeSupport {

    private static final Duration WAIT = Duration.ofSeconds(60);
    private static final String WHO = "Eva (care centre)";

    @Test
    public void theCaregiverAcknowledgesOnTheBoardAndTheFlatTakesIt() throws Exception {
        setPasswords();
        try (Mosquitto broker = Mosquitto.startDefault(); Chromium browser = Chromium.start(WAIT)) {
            Path keys = MqttBridgeSupport.flatKeyDir("flat-7", "flat-7-key-0123456789abcdef");
            configure("org.tinysep.mqtt", Map.of("brokerUrl", broker.url(), "flatId", "flat-7",
                    "queueDir", Files.createTempDirectory("tinysep-board-browser").toString(), "allowAnonymous", "true",
                    "keyFile", keys.resolve("flat-7.key").toString()));
            configure("org.tinysep.mqtt.board", Map.of("brokerUrl", broker.url(), "clientId", "browser-board",
                    "allowAnonymous", "true", "flatKeyDir", keys.toString()));
            AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
            try {
                browser.navigate(base() + "/login.html");
                browser.waitFor("document.readyState === 'complete' && document.getElementById('user') !== null", WAIT, "the login page");
                browser.eval("(document.getElementById('user').value = 'caregiver', document.getElementById('password').value = "
                        + Chromium.quote(CAREGIVER_PASSWORD) + ", document.getElementById('submit').click(), 1)");
                browser.waitFor("location.pathname === '/caregiver.html'", WAIT, "the caregiver view after logging in");

                browser.navigate(base() + "/board/");
                browser.waitFor("document.getElementById('who').textContent === 'logged in as caregiver'", WAIT, "the board page");
                browser.waitFor(row("flat-7") + " && " + row("flat-7") + ".textContent.includes('Flat flat-7: online since')",
                        WAIT, "flat-7 listed online, in words");
                String link = browser.eval("document.getElementById('link').textContent");
                assertTrue(link, link.matches("\"Broker: connected to tcp://127\\.0\\.0\\.1:\\d+ since \\d\\d:\\d\\d\""));

                Alert a = alerts.raise(new AlertRequest(AlertKind.INACTIVITY, "board-browser-test", "", "Bathroom", Instant.now(),
                        "TinySEP: no activity in Bathroom since 13:15", "Inactivity Recognition raised an alert."));
                String open = row("flat-7") + ".querySelector('.alert-open')";
                browser.waitFor(open + " !== null && " + open + ".querySelector('button') !== null", WAIT, "the open alert with its button");
                String words = browser.eval(open + ".textContent");
                assertTrue(words, words.startsWith("\"OPEN · ") && words.contains("no activity in Bathroom since 13:15"));
                assertTrue("plain words, no JSON or exception: " + words, !words.contains("{") && !words.contains("Exception"));
                shot(browser, "board");

                browser.eval("(window.prompt = () => " + Chromium.quote(WHO) + ", " + open + ".querySelector('button').click(), 1)");
                await(WAIT, () -> alerts.alert(a.id()).orElseThrow().state() == AlertState.ACKNOWLEDGED,
                        "the flat's alert service to take the acknowledgement from the board's button");
                assertEquals(WHO, alerts.alert(a.id()).orElseThrow().closedBy());
                browser.waitFor("document.getElementById('message').textContent.length > 0", WAIT, "the page's answer to the click");
                String answer = browser.eval("document.getElementById('message').textContent");
                assertTrue(answer, !answer.contains("Not acknowledged"));
                String acked = row("flat-7") + ".querySelector('.alert-acknowledged')";
                browser.waitFor(acked + " !== null && " + acked + ".textContent.includes('the flat confirmed it at')", WAIT,
                        "the flat's confirmation on the page");
                assertEquals("no Acknowledge button left", "0", browser.eval(row("flat-7") + ".querySelectorAll('button').length"));
                shot(browser, "board-acknowledged");
            } catch (AssertionError | RuntimeException e) {
                Path file = Path.of("target", "web-screenshots", "failure-board.png").toAbsolutePath();
                try {
                    browser.screenshot(file);
                    log.error("Board browser test failed; screenshot: {}", file);
                } catch (AssertionError | RuntimeException ignored) {
                    log.error("Board browser test failed; no screenshot could be taken");
                }
                throw e;
            }
        }
    }

    /** @return a JavaScript expression: the board's table row of that flat, or undefined */
    private static String row(String flat) {
        return "Array.from(document.querySelectorAll('#flats tr')).find(r => r.cells[0].textContent === " + Chromium.quote(flat) + ")";
    }

    private void shot(Chromium browser, String name) throws Exception {
        browser.waitFor("document.readyState === 'complete'", WAIT, "the page loaded");
        browser.screenshot(Path.of("target", "web-screenshots", name + ".png").toAbsolutePath());
    }
}

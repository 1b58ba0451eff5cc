package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.http.HttpResponse;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.itests.AmicaNode;
import org.junit.Before;
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

/**
 * The console's alerts over real HTTP with the real alert service (issues 12.3 and 13): an open alert is listed for
 * the caregiver, who acknowledges it (the service records who); acknowledging it again is refused (409) in words,
 * an unknown id is 404, a bad id 400; no CSRF token 403, no login 401. With the Sensor Health service (issue 13,
 * caregiver view): a movement node in the Bathroom reporting a low battery, then falling silent, shows up in
 * {@code GET /api/caregiver/sensors} in plain words (low battery, offline, the Bathroom unmonitored).
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WebAlertsTest extends WebTestSupport {

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts", "org.tinysep.sensorhealth");
    }

    /** A movement node promises a report every 2 s: OFFLINE after 3 missed reports (6 s of silence). */
    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        return replacing(super.initialConfigurations(), UDP_PID,
                Map.of("port", "0", "bindAddress", "127.0.0.1", "silentAfterIntervals", "3"));
    }

    @Before
    public void passwords() {
        setPasswords();
    }

    @Test
    public void theCaregiverSeesAndAcknowledgesAnOpenAlert() {
        AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
        Login caregiver = login("caregiver", CAREGIVER_PASSWORD);
        await(TIMEOUT, () -> call("GET", "/api/alerts", null, caregiver, false).body()
                .startsWith("{\"alertService\":true"), "the console to see the alert service");

        Alert raised = alerts.raise(new AlertRequest(AlertKind.INACTIVITY, "web-test", "", "Bathroom <b>1</b>",
                Instant.parse("2026-11-25T14:00:00Z"), "TinySEP: no activity in Bathroom <b>1</b> since 13:15",
                "Inactivity Recognition raised an alert."));
        String list = call("GET", "/api/alerts", null, caregiver, false).body();
        assertTrue(list, list.contains("\"id\":\"" + raised.id() + "\"") && list.contains("\"state\":\"OPEN\""));
        assertTrue("user text stays text in JSON: " + list, list.contains("Bathroom \\u003cb\\u003e1")
                || list.contains("Bathroom <b>1"));

        String ack = "/api/alerts/" + raised.id() + "/acknowledge";
        assertEquals(401, call("POST", ack, null, null, false).statusCode());
        assertEquals(403, call("POST", ack, null, caregiver, false).statusCode());
        assertEquals(404, call("POST", "/api/alerts/no-such-alert/acknowledge", null, caregiver, true)
                .statusCode());
        assertEquals(400, call("POST", "/api/alerts/a%20b/acknowledge", null, caregiver, true).statusCode());
        HttpResponse<String> done = call("POST", ack, null, caregiver, true);
        assertEquals(done.body(), 200, done.statusCode());
        Alert after = alerts.alert(raised.id()).orElseThrow();
        assertEquals(AlertState.ACKNOWLEDGED, after.state());
        assertEquals("caregiver (web console)", after.closedBy());
        HttpResponse<String> again = call("POST", ack, null, caregiver, true);
        assertEquals(again.body(), 409, again.statusCode());
        assertTrue(call("GET", "/api/alerts", null, caregiver, false).body().contains("\"alerts\":[]"));
    }

    @Test
    public void theCaregiverSeesOfflineSensorsLowBatteriesAndUnmonitoredRooms() throws Exception {
        Login caregiver = login("caregiver", CAREGIVER_PASSWORD);
        assertEquals(401, call("GET", "/api/caregiver/sensors", null, null, false).statusCode());
        await(TIMEOUT, () -> call("GET", "/api/caregiver/sensors", null, caregiver, false).body()
                .startsWith("{\"sensorHealth\":true"), "the console to see the sensor health service");
        shell("tinysep:room-add Bathroom Bathroom");
        try (AmicaNode node = awakeNode(1, 21, AmicaNodeType.MOVEMENT)) {
            String movement = awaitDevice(caregiver, "AmicaMovement", "1.21");
            shell("tinysep:set " + movement + " room Bathroom");
            // two AA cells near empty (the bus radio's lowBatteryMillivolts is 2200)
            node.send(new KeepAlive(300, 2150, 0x0A11, AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 4242));
            await(TIMEOUT, () -> call("GET", "/api/caregiver/sensors", null, caregiver, false).body()
                    .contains("in the Bathroom is low (2150 mV): replace or recharge it soon"), "the low battery");
            // then the node falls silent
            await(TIMEOUT, () -> call("GET", "/api/caregiver/sensors", null, caregiver, false).body()
                    .contains("\"unmonitored\":[{"), "the Bathroom unmonitored");
            String sensors = call("GET", "/api/caregiver/sensors", null, caregiver, false).body();
            assertTrue(sensors, sensors.contains("\"summary\":\"The Bathroom has no working motion sensor\""));
            assertTrue(sensors, sensors.contains("a fall or a long stillness there cannot be noticed"));
            assertTrue(sensors, sensors.contains("\"offline\":[{\"deviceUid\":"));
            assertTrue(sensors, sensors.contains("(node 1.21) in the Bathroom has been silent\""));
            assertTrue(sensors, sensors.contains("\"since\":\"20"));
            assertTrue(sensors, sensors.contains("the Bathroom has no working sensor now"));

            node.keepAlive(); // reports again: no longer offline, the room watched again
            await(TIMEOUT, () -> call("GET", "/api/caregiver/sensors", null, caregiver, false).body()
                    .contains("\"unmonitored\":[],\"offline\":[]"), "the node back online");
        }
    }
}

package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.Before;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.itests.AmicaNode;

/**
 * The console API's second slice over real HTTP on the real platform: applications (upload to install and update,
 * enable/disable through the drivers list, uninstall), room neighbour links, enumerated parameters, the decoded
 * packet log, the caregiver's activity timeline and the alerts seam; for each, bad input (4xx with a clear message),
 * no login (401), the caregiver (403) and a missing CSRF token (403).
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WebConsoleApiTest extends WebTestSupport {

    private static final String SPEAKER = "org.tinysep.amica.speaker";

    /** AmICA Speaker is not provisioned: the tests upload it. */
    @Override
    protected List<String> applications() {
        List<String> all = new ArrayList<>(super.applications());
        all.remove(SPEAKER);
        return all;
    }

    @Before
    public void passwords() {
        setPasswords();
    }

    /** Pax Exam's probe bundle runs at the application level; the drivers list leaves it out as infrastructure. */
    @Test
    public void theDriversListLeavesOutTheTestProbe() {
        Login installer = login("installer", INSTALLER_PASSWORD);
        String all = call("GET", "/api/applications?all=true", null, installer, false).body();
        assertTrue("the probe is at the application level: " + all, all.matches(
                "(?s).*\\{\"symbolicName\":\"PAXEXAM-PROBE[^{]*\"infrastructure\":true.*"));
        String apps = call("GET", "/api/applications", null, installer, false).body();
        assertFalse(apps, apps.contains("PAXEXAM"));
        assertTrue(apps, apps.contains("\"symbolicName\":\"org.tinysep.amica.protocol\""));
        assertFalse(apps, apps.contains("\"infrastructure\""));
    }

    @Test
    public void anApplicationIsUploadedUpdatedSwitchedAndUninstalled() {
        Login installer = login("installer", INSTALLER_PASSWORD);
        Login caregiver = login("caregiver", CAREGIVER_PASSWORD);
        byte[] jar = reactorJar(SPEAKER);
        assertEquals(401, upload("/api/applications", jar, "application/java-archive", null, false).statusCode());
        assertEquals(403, upload("/api/applications", jar, "application/java-archive", installer, false).statusCode());
        HttpResponse<String> asCaregiver = upload("/api/applications", jar, "application/java-archive", caregiver, true);
        assertEquals(403, asCaregiver.statusCode());
        assertTrue(asCaregiver.body(), asCaregiver.body().contains("log in as installer"));
        HttpResponse<String> notJar = upload("/api/applications", "hello".getBytes(), "application/java-archive", installer, true);
        assertEquals(400, notJar.statusCode());
        assertTrue(notJar.body(), notJar.body().contains("not a jar file"));
        HttpResponse<String> wrongType = upload("/api/applications", jar, "text/plain", installer, true);
        assertEquals(415, wrongType.statusCode());
        assertTrue(wrongType.body(), wrongType.body().contains("application/java-archive"));
        assertFalse(call("GET", "/api/applications", null, installer, false).body().contains(SPEAKER));

        HttpResponse<String> installed = upload("/api/applications", jar, "application/java-archive", installer, true);
        assertEquals(installed.body(), 200, installed.statusCode());
        assertTrue(installed.body(), installed.body().contains("\"action\":\"installed\""));
        await(Duration.ofSeconds(30), () -> call("GET", "/api/drivers", null, installer, false).body().contains("\"name\":\"AmicaSpeaker\""),
                "the uploaded AmicaSpeaker driver in GET /api/drivers");
        await(Duration.ofSeconds(30), () -> {
            String apps = call("GET", "/api/applications", null, caregiver, false).body();
            return apps.contains("\"symbolicName\":\"" + SPEAKER + "\"") && apps.contains("\"uploaded\":true")
                    && apps.contains("{\"uid\":") && apps.contains("\"name\":\"AmicaSpeaker\"");
        }, "the speaker application with its driver, uploaded");

        HttpResponse<String> updated = upload("/api/applications", jar, "application/java-archive", installer, true);
        assertEquals(updated.body(), 200, updated.statusCode());
        assertTrue(updated.body(), updated.body().contains("\"action\":\"updated\""));
        assertTrue(updated.body(), updated.body().contains("\"note\":\"\""));

        // the drivers list adopts what the console installed (it appends file: installs from outside the deploy folder)
        await(Duration.ofSeconds(30), () -> call("GET", "/api/applications", null, installer, false).body()
                .matches("(?s).*\"symbolicName\":\"" + SPEAKER + "\"[^}]*\"listed\":true.*"), "the speaker in the drivers list");
        assertEquals(403, call("POST", "/api/applications/" + SPEAKER + "/disable", null, installer, false).statusCode());
        assertEquals(403, call("POST", "/api/applications/" + SPEAKER + "/disable", null, caregiver, true).statusCode());
        HttpResponse<String> disabled = call("POST", "/api/applications/" + SPEAKER + "/disable", null, installer, true);
        assertEquals(disabled.body(), 200, disabled.statusCode());
        await(Duration.ofSeconds(30), () -> !call("GET", "/api/drivers", null, installer, false).body().contains("\"name\":\"AmicaSpeaker\""),
                "the disabled speaker's driver gone");
        assertEquals(200, call("POST", "/api/applications/" + SPEAKER + "/enable", null, installer, true).statusCode());
        await(Duration.ofSeconds(30), () -> call("GET", "/api/drivers", null, installer, false).body().contains("\"name\":\"AmicaSpeaker\""),
                "the enabled speaker's driver back");
        HttpResponse<String> unknown = call("POST", "/api/applications/org.example.nothing/enable", null, installer, true);
        assertEquals(404, unknown.statusCode());
        assertTrue(unknown.body(), unknown.body().contains("no application org.example.nothing"));
        assertEquals(400, call("POST", "/api/applications/bad%20name/enable", null, installer, true).statusCode());
        assertEquals(200, call("POST", "/api/applications/reload", null, installer, true).statusCode());

        HttpResponse<String> platform = call("DELETE", "/api/applications/org.tinysep.runtime", null, installer, true);
        assertEquals(platform.body(), 409, platform.statusCode());
        assertTrue(platform.body(), platform.body().contains("platform bundle"));
        assertEquals(403, call("DELETE", "/api/applications/" + SPEAKER, null, installer, false).statusCode());
        HttpResponse<String> removed = call("DELETE", "/api/applications/" + SPEAKER, null, installer, true);
        assertEquals(removed.body(), 200, removed.statusCode());
        await(Duration.ofSeconds(30), () -> !call("GET", "/api/drivers", null, installer, false).body().contains("\"name\":\"AmicaSpeaker\""),
                "the uninstalled speaker's driver gone");
        // the drivers list hears of the uninstall through an asynchronous bundle event: its entry goes a moment later
        await(Duration.ofSeconds(30), () -> !call("GET", "/api/applications", null, installer, false).body()
                .contains("\"symbolicName\":\"" + SPEAKER + "\""), "the speaker gone from the applications and the drivers list");
        assertEquals(404, call("DELETE", "/api/applications/" + SPEAKER, null, installer, true).statusCode());
        assertEquals(401, call("GET", "/api/applications", null, null, false).statusCode());
        // every changing call of this slice: 401 without login, 403 without the CSRF header, 403 for the caregiver
        for (String[] c : new String[][] {{"POST", "/api/applications/reload"}, {"POST", "/api/applications/" + SPEAKER + "/enable"},
                {"POST", "/api/applications/" + SPEAKER + "/disable"}, {"DELETE", "/api/applications/" + SPEAKER},
                {"PUT", "/api/rooms/x/neighbours/y"}, {"DELETE", "/api/rooms/x/neighbours/y"}, {"POST", "/api/alerts/a-1/acknowledge"}}) {
            String what = c[0] + " " + c[1];
            assertEquals(what, 401, call(c[0], c[1], null, null, false).statusCode());
            HttpResponse<String> noCsrf = call(c[0], c[1], null, installer, false);
            assertEquals(what, 403, noCsrf.statusCode());
            assertTrue(what + ": " + noCsrf.body(), noCsrf.body().contains("CSRF"));
            if (!c[1].endsWith("/acknowledge")) {
                HttpResponse<String> role = call(c[0], c[1], null, caregiver, true);
                assertEquals(what, 403, role.statusCode());
                assertTrue(what + ": " + role.body(), role.body().contains("log in as installer"));
            }
        }
    }

    @Test
    public void roomsAreLinkedBothWaysAndNamesStayText() {
        Login installer = login("installer", INSTALLER_PASSWORD);
        String evil = "<img src=x onerror=alert(1)>";
        HttpResponse<String> a = call("POST", "/api/rooms", "{\"name\":\"" + evil + "\",\"type\":\"Hall\"}", installer, true);
        assertEquals(a.body(), 200, a.statusCode());
        assertFalse(a.body(), a.body().contains("<img"));
        assertTrue(a.body(), a.body().contains("\\u003cimg src=x onerror=alert(1)\\u003e"));
        String hall = field(a.body(), "uid");
        String bath = field(call("POST", "/api/rooms", "{\"name\":\"Bath\",\"type\":\"Bathroom\"}", installer, true).body(), "uid");
        assertEquals(403, call("PUT", "/api/rooms/" + hall + "/neighbours/" + bath, null, installer, false).statusCode());
        Login caregiver = login("caregiver", CAREGIVER_PASSWORD);
        assertEquals(403, call("PUT", "/api/rooms/" + hall + "/neighbours/" + bath, null, caregiver, true).statusCode());
        assertEquals(401, call("PUT", "/api/rooms/" + hall + "/neighbours/" + bath, null, null, false).statusCode());
        HttpResponse<String> linked = call("PUT", "/api/rooms/" + hall + "/neighbours/" + bath, null, installer, true);
        assertEquals(linked.body(), 200, linked.statusCode());
        assertTrue(linked.body(), linked.body().contains("\"neighbours\":[\"" + bath + "\"]"));
        String rooms = call("GET", "/api/rooms", null, caregiver, false).body();
        assertTrue("both ways: " + rooms, rooms.contains("\"uid\":\"" + bath + "\",\"name\":\"Bath\",\"type\":\"Bathroom\",\"neighbours\":[\"" + hall + "\"]"));
        HttpResponse<String> self = call("PUT", "/api/rooms/" + hall + "/neighbours/" + hall, null, installer, true);
        assertEquals(400, self.statusCode());
        assertTrue(self.body(), self.body().contains("its own neighbour"));
        HttpResponse<String> nowhere = call("PUT", "/api/rooms/" + hall + "/neighbours/no-such-room", null, installer, true);
        assertEquals(404, nowhere.statusCode());
        assertTrue(nowhere.body(), nowhere.body().contains("no room with UID no-such-room"));
        HttpResponse<String> blank = call("PUT", "/api/rooms/" + hall, "{\"name\":\"  \"}", installer, true);
        assertEquals(400, blank.statusCode());
        HttpResponse<String> unlinked = call("DELETE", "/api/rooms/" + hall + "/neighbours/" + bath, null, installer, true);
        assertEquals(unlinked.body(), 200, unlinked.statusCode());
        assertTrue(unlinked.body(), unlinked.body().contains("\"neighbours\":[]"));
        assertEquals(200, call("DELETE", "/api/rooms/" + hall, null, installer, true).statusCode());
        assertEquals(200, call("DELETE", "/api/rooms/" + bath, null, installer, true).statusCode());
    }

    @Test
    public void packetsAreDecodedEnumsHaveOptionsAndTheCaregiverHasATimelineAndAlerts() throws Exception {
        Login installer = login("installer", INSTALLER_PASSWORD);
        Login caregiver = login("caregiver", CAREGIVER_PASSWORD);
        String kitchen = field(call("POST", "/api/rooms", "{\"name\":\"Kitchen\",\"type\":\"Kitchen\"}", installer, true).body(), "uid");
        try (AmicaNode door = awakeNode(1, 40, AmicaNodeType.DOOR)) {
            String uid = awaitDevice(installer, "AmicaDoor", "1.40");
            String device = call("GET", "/api/devices/" + uid, null, caregiver, false).body();
            assertTrue(device, device.contains("\"options\":[\"OUTER\",\"INNER\"]"));
            assertTrue(device, device.contains("{\"key\":\"name\",") && device.contains("\"description\":\"name shown to the user\",\"options\":[]"));
            assertEquals(200, call("PUT", "/api/devices/" + uid + "/parameters/room", "{\"value\":\"" + kitchen + "\"}", installer, true).statusCode());
            door.door(true);
            await(Duration.ofSeconds(30), () -> call("GET", "/api/packets?origin=node%201.40&limit=20", null, caregiver, false).body()
                    .contains("reed switch open"), "the door's frame decoded in the packet log");
            String packets = call("GET", "/api/packets?origin=node%201.40&limit=20", null, caregiver, false).body();
            assertTrue(packets, packets.contains("\"decoded\":\"AmICA 1.40 → 1.0 #"));
            assertTrue(packets, packets.contains("keep-alive"));
            assertTrue(packets, packets.contains("\"node\":\"1.40\""));

            await(Duration.ofSeconds(30), () -> call("GET", "/api/caregiver/timeline?days=1", null, caregiver, false).body()
                    .matches("(?s).*\"uid\":\"" + kitchen + "\"[^}]*\"counts\":\\[[0-9,]*[1-9][0-9,]*\\].*"), "the door's activity in the kitchen's timeline");
            String day = call("GET", "/api/caregiver/timeline?days=1", null, caregiver, false).body();
            assertTrue(day, day.contains("\"slotMinutes\":30"));
            String week = call("GET", "/api/caregiver/timeline?days=7", null, caregiver, false).body();
            assertTrue(week, week.contains("\"slotMinutes\":120"));
            HttpResponse<String> bad = call("GET", "/api/caregiver/timeline?days=3", null, caregiver, false);
            assertEquals(400, bad.statusCode());
            assertTrue(bad.body(), bad.body().contains("days must be 1 or 7"));
            assertEquals(401, call("GET", "/api/caregiver/timeline", null, null, false).statusCode());
        }

        HttpResponse<String> alerts = call("GET", "/api/alerts", null, caregiver, false);
        assertEquals(200, alerts.statusCode());
        assertTrue(alerts.body(), alerts.body().startsWith("{\"alertService\":false,\"message\":\"no alert service"));
        assertTrue(alerts.body(), alerts.body().contains("\"inactivity\":{\"state\":"));
        assertEquals(401, call("GET", "/api/alerts", null, null, false).statusCode());
        assertEquals(403, call("POST", "/api/alerts/a-1/acknowledge", null, caregiver, false).statusCode());
        HttpResponse<String> ack = call("POST", "/api/alerts/a-1/acknowledge", null, caregiver, true);
        assertEquals("the caregiver may acknowledge, but there is no alert service yet: " + ack.body(), 503, ack.statusCode());
        assertTrue(ack.body(), ack.body().contains("no alert service"));
        assertEquals(400, call("POST", "/api/alerts/a%20b/acknowledge", null, installer, true).statusCode());
        assertEquals(403, call("POST", "/api/alerts/a-1/dismiss", null, caregiver, true).statusCode());

        // no Sensor Health bundle here: the caregiver's sensor list says so plainly
        HttpResponse<String> sensors = call("GET", "/api/caregiver/sensors", null, caregiver, false);
        assertEquals(200, sensors.statusCode());
        assertTrue(sensors.body(), sensors.body().startsWith("{\"sensorHealth\":false,\"message\":\"no sensor health "
                + "service: the Sensor Health bundle (org.tinysep.sensorhealth) is not running"));
        assertEquals(401, call("GET", "/api/caregiver/sensors", null, null, false).statusCode());
        assertEquals("read only", 404, call("POST", "/api/caregiver/sensors", null, installer, true).statusCode());
    }
}

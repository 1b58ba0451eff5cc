package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.BufferedReader;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.net.URI;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.Before;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.itests.AmicaNode;

/**
 * The web console's API over real HTTP (Jetty 12 on a free port of 127.0.0.1) on the real platform, with real UDP
 * frames: login, roles, CSRF, validation messages, log queries, rooms, the live event stream, JSON escaping.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WebApiTest extends WebTestSupport {

    @Before
    public void passwords() {
        setPasswords();
    }

    @Test
    public void nothingWithoutLogin() {
        for (String path : new String[] {"/api/devices", "/api/drivers", "/api/rooms", "/api/events", "/api/packets",
                "/api/caregiver", "/api/session", "/api/stream/events"}) {
            HttpResponse<String> r = call("GET", path, null, null, false);
            assertEquals(path, 401, r.statusCode());
            assertTrue(path + ": " + r.body(), r.body().contains("log in first") || r.body().contains("not logged in"));
        }
        for (String page : new String[] {"/", "/index.html", "/devices.html", "/caregiver.html", "/common.js"}) {
            HttpResponse<String> r = call("GET", page, null, null, false);
            assertEquals(page, 302, r.statusCode());
            assertEquals("/login.html", r.headers().firstValue("Location").orElse(""));
        }
        HttpResponse<String> loginPage = call("GET", "/login.html", null, null, false);
        assertEquals(200, loginPage.statusCode());
        assertTrue(loginPage.headers().firstValue("Content-Security-Policy").orElse("").contains("script-src 'self'"));
        assertEquals(401, call("PUT", "/api/devices/x/parameters/name", "{\"value\":\"y\"}", null, false).statusCode());
    }

    /**
     * Issue 25, item 8: Jetty answers a malformed request itself (400, before any filter runs); its page carries the
     * same security headers as every answer of the console.
     */
    @Test
    public void jettysOwnErrorPagesCarryTheSecurityHeaders() {
        HttpResponse<String> page = call("GET", "/login.html", null, null, false);
        for (String malformed : new String[] {"GARBAGE\r\n\r\n",
                "GET /login.html HTTP/1.1\r\nHost: 127.0.0.1\r\nno colon in this header\r\n\r\n",
                "GET /login.html HTTP/9.9\r\nHost: 127.0.0.1\r\n\r\n"}) {
            String answer = raw("127.0.0.1", malformed);
            assertTrue(answer, answer.startsWith("HTTP/1.1 400 ") || answer.startsWith("HTTP/1.1 505 "));
            String head = answer.substring(0, Math.max(0, answer.indexOf("\r\n\r\n"))).toLowerCase(java.util.Locale.ROOT);
            for (String name : new String[] {"Content-Security-Policy", "X-Content-Type-Options", "X-Frame-Options",
                    "Referrer-Policy"}) {
                String expected = page.headers().firstValue(name).orElseThrow();
                assertTrue(name + " in Jetty's page for " + malformed.strip() + ":\n" + answer,
                        head.contains("\r\n" + name.toLowerCase(java.util.Locale.ROOT) + ": " + expected.toLowerCase(java.util.Locale.ROOT)));
            }
        }
    }

    @Test
    public void loginGivesAStrictHttpOnlyCookieAndRefusesWrongPasswords() {
        HttpResponse<String> wrong = call("POST", "/api/session", "{\"user\":\"installer\",\"password\":\"nope-nope\"}", null, false);
        assertEquals(401, wrong.statusCode());
        assertTrue(wrong.body(), wrong.body().contains("wrong user name or password"));
        assertTrue(wrong.headers().firstValue("Set-Cookie").isEmpty());
        HttpResponse<String> noJson = call("POST", "/api/session", null, null, false);
        assertEquals(415, noJson.statusCode());

        Login login = login("installer", INSTALLER_PASSWORD);
        assertTrue(login.setCookie(), login.setCookie().contains("HttpOnly"));
        assertTrue(login.setCookie(), login.setCookie().contains("SameSite=Strict"));
        assertFalse("no TLS here, so no Secure flag: " + login.setCookie(), login.setCookie().contains("Secure"));
        HttpResponse<String> who = call("GET", "/api/session", null, login, false);
        assertEquals(200, who.statusCode());
        assertTrue(who.body(), who.body().contains("\"role\":\"installer\""));
        assertEquals(200, call("GET", "/index.html", null, login, false).statusCode());

        assertEquals(200, call("DELETE", "/api/session", null, login, true).statusCode());
        assertEquals("logged out", 401, call("GET", "/api/devices", null, login, false).statusCode());
    }

    @Test
    public void changesNeedTheCsrfToken() {
        Login login = login("installer", INSTALLER_PASSWORD);
        HttpResponse<String> none = call("POST", "/api/rooms", "{\"name\":\"Hall\",\"type\":\"Hall\"}", login, false);
        assertEquals(403, none.statusCode());
        assertTrue(none.body(), none.body().contains("CSRF"));
        Login forged = new Login(login.cookie(), "forged-token", login.setCookie());
        assertEquals(403, call("POST", "/api/rooms", "{\"name\":\"Hall\",\"type\":\"Hall\"}", forged, true).statusCode());
        assertFalse(call("GET", "/api/rooms", null, login, false).body().contains("Hall"));
        HttpResponse<String> ok = call("POST", "/api/rooms", "{\"name\":\"Hall\",\"type\":\"Hall\"}", login, true);
        assertEquals(ok.body(), 200, ok.statusCode());
        assertTrue(call("GET", "/api/rooms", null, login, false).body().contains("\"name\":\"Hall\""));
    }

    @Test
    public void theCaregiverMayReadButNotChange() {
        Login caregiver = login("caregiver", CAREGIVER_PASSWORD);
        assertEquals(200, call("GET", "/api/devices", null, caregiver, false).statusCode());
        assertEquals(200, call("GET", "/api/caregiver", null, caregiver, false).statusCode());
        HttpResponse<String> r = call("POST", "/api/rooms", "{\"name\":\"Attic\",\"type\":\"Attic\"}", caregiver, true);
        assertEquals(403, r.statusCode());
        assertTrue(r.body(), r.body().contains("log in as installer"));
        assertEquals("the caregiver may still log out", 200, call("DELETE", "/api/session", null, caregiver, true).statusCode());
    }

    @Test
    public void aBadParameterIs400WithTheDevicesMessage() throws Exception {
        Login login = login("installer", INSTALLER_PASSWORD);
        try (AmicaNode door = awakeNode(1, 20, AmicaNodeType.DOOR)) {
            String uid = awaitDevice(login, "AmicaDoor", "1.20");
            HttpResponse<String> bad = call("PUT", "/api/devices/" + uid + "/parameters/kind", "{\"value\":\"SIDEWAYS\"}", login, true);
            assertEquals(bad.body(), 400, bad.statusCode());
            assertTrue(bad.body(), bad.body().startsWith("{\"error\":\"kind: "));
            assertTrue(bad.body(), bad.body().contains("SIDEWAYS"));
            HttpResponse<String> unknown = call("PUT", "/api/devices/" + uid + "/parameters/colour", "{\"value\":\"red\"}", login, true);
            assertEquals(400, unknown.statusCode());
            assertEquals(404, call("PUT", "/api/devices/no-such-uid/parameters/kind", "{\"value\":\"INNER\"}", login, true).statusCode());
            assertEquals(400, call("PUT", "/api/devices/" + uid + "/parameters/kind", "{\"value\": [1]}", login, true).statusCode());
            HttpResponse<String> good = call("PUT", "/api/devices/" + uid + "/parameters/kind", "{\"value\":\"INNER\"}", login, true);
            assertEquals(good.body(), 200, good.statusCode());
            assertTrue(good.body(), good.body().contains("{\"key\":\"kind\",\"value\":\"INNER\""));
        }
    }

    @Test
    public void aUdpFrameShowsUpInTheLiveEventStream() throws Exception {
        Login login = login("installer", INSTALLER_PASSWORD);
        try (AmicaNode movement = awakeNode(1, 17, AmicaNodeType.MOVEMENT)) {
            String uid = awaitDevice(login, "AmicaMovement", "1.17");
            HttpRequest request = HttpRequest.newBuilder(URI.create(base() + "/api/stream/events"))
                    .header("Cookie", login.cookie()).GET().build();
            HttpResponse<InputStream> stream = http.send(request, HttpResponse.BodyHandlers.ofInputStream());
            assertEquals(200, stream.statusCode());
            assertTrue(stream.headers().firstValue("Content-Type").orElse("").startsWith("text/event-stream"));
            CompletableFuture<String> line = CompletableFuture.supplyAsync(() -> {
                try (BufferedReader in = new BufferedReader(new InputStreamReader(stream.body(), StandardCharsets.UTF_8))) {
                    for (String l = in.readLine(); l != null; l = in.readLine()) {
                        if (l.startsWith("data:") && l.contains("\"origin\":\"" + uid + "\"") && l.contains("movement detected")) {
                            return l;
                        }
                    }
                    return "stream ended";
                } catch (Exception e) {
                    return e.toString();
                }
            });
            // frames until the stream has shown one (the stream may open after the first one was logged)
            long deadline = System.nanoTime() + Duration.ofSeconds(30).toNanos();
            while (!line.isDone() && System.nanoTime() < deadline) {
                movement.motion(true);
                try {
                    line.get(1, TimeUnit.SECONDS);
                } catch (java.util.concurrent.TimeoutException e) {
                    movement.motion(false);
                }
            }
            String seen = line.getNow("nothing within 30 s");
            stream.body().close();
            assertTrue(seen, seen.contains("movement detected"));
            assertTrue(seen, seen.contains("\"originName\":\"Movement sensor 1.17\"") || seen.contains("\"originName\":"));
        }
    }

    @Test
    public void userGivenTextIsEscapedAndLogsCanBeSearched() throws Exception {
        Login login = login("installer", INSTALLER_PASSWORD);
        try (AmicaNode door = awakeNode(1, 21, AmicaNodeType.DOOR)) {
            String uid = awaitDevice(login, "AmicaDoor", "1.21");
            String evil = "<script>alert(1)</script>";
            HttpResponse<String> renamed = call("PUT", "/api/devices/" + uid + "/parameters/name",
                    "{\"value\":\"" + evil.replace("/", "\\/") + "\"}", login, true);
            assertEquals(renamed.body(), 200, renamed.statusCode());
            String devices = call("GET", "/api/devices", null, login, false).body();
            assertFalse(devices, devices.contains("<script>"));
            assertTrue(devices, devices.contains("\\u003cscript\\u003ealert(1)\\u003c/script\\u003e"));

            String events = call("GET", "/api/events?kind=DEVICE_EVENT&origin=" + uid + "&limit=50", null, login, false).body();
            assertTrue(events, events.contains("renamed to"));
            assertFalse(events, events.contains("\"kind\":\"DEVICE_CREATED\""));
            HttpResponse<String> badKind = call("GET", "/api/events?kind=EXPLODED", null, login, false);
            assertEquals(400, badKind.statusCode());
            assertTrue(badKind.body(), badKind.body().contains("unknown kind 'EXPLODED'"));
            assertEquals(400, call("GET", "/api/events?limit=0", null, login, false).statusCode());
            assertEquals(400, call("GET", "/api/events?from=yesterday", null, login, false).statusCode());
            String packets = call("GET", "/api/packets?origin=node%201.21&kind=RECEIVED&limit=5", null, login, false).body();
            assertTrue(packets, packets.contains("\"direction\":\"RECEIVED\""));
            assertTrue(packets, packets.contains("\"hex\":\""));
        }
    }

    @Test
    public void roomsCanBeAddedUsedAndRemoved() throws Exception {
        Login login = login("installer", INSTALLER_PASSWORD);
        HttpResponse<String> added = call("POST", "/api/rooms", "{\"name\":\"Kitchen\",\"type\":\"Kitchen\"}", login, true);
        assertEquals(added.body(), 200, added.statusCode());
        String roomUid = field(added.body(), "uid");
        assertEquals(400, call("POST", "/api/rooms", "{\"name\":\" \",\"type\":\"Kitchen\"}", login, true).statusCode());
        try (AmicaNode movement = awakeNode(1, 30, AmicaNodeType.MOVEMENT)) {
            String uid = awaitDevice(login, "AmicaMovement", "1.30");
            HttpResponse<String> placed = call("PUT", "/api/devices/" + uid + "/parameters/room", "{\"value\":\"" + roomUid + "\"}", login, true);
            assertEquals(placed.body(), 200, placed.statusCode());
            assertTrue(placed.body(), placed.body().contains("\"room\":{\"uid\":\"" + roomUid + "\",\"name\":\"Kitchen\"}")
                    || placed.body().contains("\"name\":\"Kitchen\""));
            movement.motion(true);
            await(Duration.ofSeconds(20), () -> call("GET", "/api/caregiver", null, login, false).body()
                    .contains("\"lastActivity\":{\"time\""), "the kitchen's last activity in the caregiver view");
            String caregiver = call("GET", "/api/caregiver", null, login, false).body();
            assertTrue(caregiver, caregiver.contains("\"room\":\"Kitchen\""));
            assertTrue(caregiver, caregiver.contains("\"occupancy\":{\"state\""));
        }
        assertEquals(200, call("DELETE", "/api/rooms/" + roomUid, null, login, true).statusCode());
        HttpResponse<String> again = call("DELETE", "/api/rooms/" + roomUid, null, login, true);
        assertEquals(404, again.statusCode());
        assertTrue(again.body(), again.body().contains("no room with UID"));
        assertEquals(404, call("GET", "/api/nothing-here", null, login, false).statusCode());
    }
}

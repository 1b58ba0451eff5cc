package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.itests.AmicaNode;

/**
 * The console in a real browser (Debian's headless Chromium over the DevTools protocol) against the real platform
 * with a small flat of real UDP nodes: log in through the form, the event log page, a live event appearing without
 * reload after a UDP frame, the devices list, the connection graph, the packet log (decoded, filtered by node), a
 * device named with HTML shown as text, the room chosen from the drop-down and saved, an enumerated parameter as a
 * drop-down, a refused value's message next to its field, a bundle uploaded on the Drivers page and its driver
 * appearing, the house plan (a room named with HTML shown as text, a neighbour link saved), the caregiver view
 * (activity plot, alerts section). Screenshots of each page go to {@code target/web-screenshots/}; on failure, a
 * screenshot of the failing page.
 * Every step waits on a condition in the page, never a fixed time.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WebBrowserTest extends WebTestSupport {

    private static final Duration WAIT = Duration.ofSeconds(30);
    private static final String XSS = "<img src=x onerror=\"window.xssFired=1\"><script>window.xssFired=1</script>";
    private static final String WINDOW = "org.tinysep.amica.window";

    /** AmICA Window is not provisioned: the test uploads it on the Drivers page. */
    @Override
    protected List<String> applications() {
        List<String> all = new ArrayList<>(super.applications());
        all.remove(WINDOW);
        all.add("org.tinysep.alerts");
        return all;
    }

    @Test
    public void theConsoleWorksInARealBrowser() throws Exception {
        setPasswords();
        String base = base();
        Login api = login("installer", INSTALLER_PASSWORD);
        int port = udpPortOf("BusRadioAmicaUdp");
        String living = room(api, "Living room", "LivingRoom");
        String kitchen = room(api, "Kitchen", "Kitchen");
        room(api, "Bathroom", "Bathroom");
        try (AmicaNode sofa = new AmicaNode(1, 17, port, AmicaNodeType.MOVEMENT);
                AmicaNode cooker = new AmicaNode(1, 18, port, AmicaNodeType.MOVEMENT);
                AmicaNode front = new AmicaNode(1, 20, port, AmicaNodeType.DOOR);
                Chromium browser = Chromium.start(WAIT)) {
            sofa.keepAlive();
            cooker.keepAlive();
            front.keepAlive();
            String sofaUid = awaitDevice(api, "AmicaMovement", "1.17");
            String cookerUid = awaitDevice(api, "AmicaMovement", "1.18");
            String doorUid = awaitDevice(api, "AmicaDoor", "1.20");
            put(api, sofaUid, "room", living);
            put(api, doorUid, "room", living);
            sofa.motion(true);
            front.door(true);
            front.door(false);
            String step = "login page";
            try {
                open(browser, base + "/",
                        "location.pathname === '/login.html' && document.readyState === 'complete'",
                        "the login page");
                shot(browser, "login");
                step = "wrong password";
                browser.eval("(document.getElementById('password').value = 'wrong-password', document.getElementById('submit').click(), 1)");
                browser.waitFor("document.getElementById('message').textContent.includes('wrong user name or password')", WAIT,
                        "the refusal of a wrong password");
                step = "login";
                browser.eval("(document.getElementById('password').value = " + Chromium.quote(INSTALLER_PASSWORD)
                        + ", document.getElementById('submit').click(), 1)");
                browser.waitFor("location.pathname === '/index.html' && document.querySelectorAll('#events tr').length > 0", WAIT,
                        "the event log after logging in");
                browser.waitFor("performance.getEntriesByName('events-shown').length > 0", WAIT, "the event log's first rows");
                metrics(browser);

                step = "live event";
                browser.waitFor("document.getElementById('live-status').textContent === 'live'", WAIT, "the live stream");
                browser.eval("(window.notReloaded = true)");
                String before = browser.eval("Array.from(document.querySelectorAll('#events tr')).filter(r => r.textContent.includes('Movement sensor 1.18') && r.textContent.includes('movement detected')).length");
                assertEquals("0", before);
                cooker.motion(true);
                browser.waitFor("Array.from(document.querySelectorAll('#events tr')).some(r => r.textContent.includes('Movement sensor 1.18') && r.textContent.includes('movement detected'))",
                        WAIT, "the movement of node 1.18 in the event log, live");
                assertEquals("the page was not reloaded", "true", browser.eval("window.notReloaded === true"));
                browser.waitFor("Array.from(document.querySelectorAll('#live li')).some(r => r.textContent.includes('movement detected'))",
                        WAIT, "the movement in the live side panel");
                shot(browser, "events");

                step = "devices";
                browser.eval("Tiny.api('PUT', 'devices/" + cookerUid + "/parameters/name', {value: " + Chromium.quote(XSS) + "}).then(() => 1)");
                open(browser, base + "/devices.html",
                        "document.querySelectorAll('#devices tr[data-uid]').length >= 6",
                        "the devices list");
                browser.waitFor("Array.from(document.querySelectorAll('#devices a')).some(a => a.textContent === " + Chromium.quote(XSS) + ")",
                        WAIT, "the device named with HTML, shown as text");
                assertEquals("no element made from a device name", "0", browser.eval("document.querySelectorAll('#main img, #main script').length"));
                assertEquals("no script from a device name ran", "false", browser.eval("window.xssFired === 1"));
                shot(browser, "devices");
                browser.eval("Tiny.api('PUT', 'devices/" + cookerUid + "/parameters/name', {value: 'Kitchen movement'}).then(() => 1)");

                step = "device settings";
                browser.eval("(location.hash = " + Chromium.quote(cookerUid) + ", 1)");
                browser.waitFor("document.getElementById('param-room') !== null", WAIT, "the settings form with the room drop-down");
                String options = browser.eval("Array.from(document.querySelectorAll('#param-room option')).map(o => o.textContent).join('|')");
                assertTrue(options, options.contains("Kitchen (Kitchen)") && options.contains("Living room (LivingRoom)"));
                browser.eval("(document.getElementById('param-room').value = " + Chromium.quote(kitchen)
                        + ", document.getElementById('save-room').click(), 1)");
                browser.waitFor("document.getElementById('error-room').textContent.startsWith('saved')", WAIT, "the room saved");
                HttpResponse<String> device = call("GET", "/api/devices/" + cookerUid, null, api, false);
                assertTrue(device.body(), device.body().contains("\"room\":{\"uid\":\"" + kitchen + "\",\"name\":\"Kitchen\"}"));
                shot(browser, "device-settings");

                step = "enumerated parameter";
                browser.eval("(location.hash = " + Chromium.quote(doorUid) + ", 1)");
                browser.waitFor("document.getElementById('param-kind') !== null && document.getElementById('param-kind').tagName === 'SELECT'",
                        WAIT, "the door's kind as a drop-down");
                assertEquals("the door's kinds as JSON text", "\"OUTER|INNER\"", browser.eval("Array.from(document.querySelectorAll('#param-kind option')).map(o => o.value).join('|')"));
                browser.eval("(document.getElementById('param-kind').value = 'INNER', document.getElementById('save-kind').click(), 1)");
                browser.waitFor("document.getElementById('error-kind').textContent.startsWith('saved')", WAIT, "the kind saved");
                assertTrue(call("GET", "/api/devices/" + doorUid, null, api, false).body().contains("{\"key\":\"kind\",\"value\":\"INNER\""));
                browser.eval("(document.getElementById('param-name').value = '   ', document.getElementById('save-name').click(), 1)");
                browser.waitFor("document.getElementById('error-name').textContent.includes('name must not be blank')", WAIT,
                        "the device's refusal next to the name field");

                step = "drivers upload";
                Path jar = Files.createTempDirectory("tinysep-upload-").resolve("window-driver.jar");
                Files.write(jar, reactorJar(WINDOW));
                open(browser, base + "/drivers.html",
                        "document.querySelectorAll('#applications tr[data-bsn]').length >= 5 && !document.getElementById('upload').hidden",
                        "the drivers list with its upload form");
                assertEquals("false", browser.eval("document.querySelector('#applications tr[data-bsn=\"" + WINDOW + "\"]') !== null"));
                assertEquals("Pax Exam's probe is infrastructure, not an application", "0",
                        browser.eval("document.querySelectorAll('#applications tr[data-bsn^=\"PAXEXAM\"]').length"));
                browser.setFile("#jar", jar);
                browser.eval("(document.getElementById('upload-button').click(), 1)");
                browser.waitFor("document.getElementById('message').textContent.includes('" + WINDOW + "')", WAIT, "the upload's answer");
                assertTrue(browser.eval("document.getElementById('message').textContent"),
                        browser.eval("document.getElementById('message').textContent").contains("installed"));
                browser.waitFor("Array.from(document.querySelectorAll('#applications tr[data-bsn=\"" + WINDOW + "\"] .driver')).some(d => d.textContent.startsWith('AmicaWindow'))",
                        WAIT, "the uploaded bundle's driver AmicaWindow in the list");
                shot(browser, "drivers");

                step = "house plan";
                open(browser, base + "/house.html",
                        "document.querySelectorAll('#rooms tr[data-uid]').length === 3 && !document.getElementById('add-room').hidden",
                        "the house plan's rooms");
                browser.eval("(document.getElementById('new-name').value = " + Chromium.quote(XSS) + ", document.getElementById('new-type').value = 'Hall',"
                        + " document.getElementById('add').click(), 1)");
                browser.waitFor("Array.from(document.querySelectorAll('#rooms input.room-name')).some(i => i.value === " + Chromium.quote(XSS) + ")",
                        WAIT, "the room named with HTML, shown as text");
                browser.waitFor("Array.from(document.querySelectorAll('#plan-svg text')).some(t => t.textContent.startsWith('<img'))", WAIT,
                        "the room named with HTML in the plan, as text");
                assertEquals("no element made from a room name", "0", browser.eval("document.querySelectorAll('#main img, #main script').length"));
                assertEquals("no script from a room name ran", "false", browser.eval("window.xssFired === 1"));
                browser.eval("(document.querySelector('#rooms tr[data-uid=\"" + kitchen + "\"] input.link[data-other=\"" + living + "\"]').click(), 1)");
                browser.waitFor("document.getElementById('message').textContent.startsWith('Linked')", WAIT, "the link saved");
                String rooms = call("GET", "/api/rooms", null, api, false).body();
                assertTrue(rooms, rooms.contains("\"uid\":\"" + kitchen + "\",\"name\":\"Kitchen\",\"type\":\"Kitchen\",\"neighbours\":[\"" + living + "\"]"));
                shot(browser, "house");

                step = "connection graph";
                open(browser, base + "/graph.html",
                        "document.querySelectorAll('#graph .node').length >= 6 && document.querySelectorAll('#graph path.edge.vital').length >= 3",
                        "the connection graph with its vital connections");
                shot(browser, "graph");

                step = "packet log";
                open(browser, base + "/packets.html",
                        "Array.from(document.querySelectorAll('#packets tr')).some(r => r.textContent.includes('node 1.18'))",
                        "the packets of node 1.18 in the packet log");
                browser.waitFor("Array.from(document.querySelectorAll('#packets tr[data-node=\"1.18\"] td.decoded')).some(d => d.textContent.endsWith('motion detected'))",
                        WAIT, "node 1.18's motion decoded");
                shot(browser, "packets");
                browser.eval("(document.getElementById('node').value = '1.17', document.getElementById('node').dispatchEvent(new Event('input')), 1)");
                browser.waitFor("Array.from(document.querySelectorAll('#packets tr')).filter(r => !r.hidden).length > 0"
                        + " && Array.from(document.querySelectorAll('#packets tr')).filter(r => !r.hidden).every(r => r.dataset.node === '1.17')",
                        WAIT, "only node 1.17's packets after filtering by node");

                step = "caregiver view";
                cooker.motion(true);
                open(browser, base + "/caregiver.html",
                        "document.querySelectorAll('#rooms tr').length === 4 && document.getElementById('occupancy').textContent !== '…'",
                        "the caregiver view");
                browser.waitFor("document.getElementById('last-activity').textContent === 'Kitchen' || document.getElementById('last-activity').textContent === 'Living room'",
                        WAIT, "the last activity's room");
                browser.waitFor("document.querySelectorAll('#timeline-svg rect.slot').length > 0 && document.querySelectorAll('#timeline-svg .room-label').length === 4",
                        WAIT, "the activity plot of the last 24 hours");
                browser.waitFor("document.getElementById('sensor-health').textContent.startsWith('no sensor health service: the Sensor"
                        + " Health bundle (org.tinysep.sensorhealth) is not running')", WAIT, "the sensors section without Sensor Health");
                // an open alert from the alert service, acknowledged with the page's button
                org.tinysep.api.alert.AlertService alertService = awaitService(
                        org.tinysep.api.alert.AlertService.class, null, TIMEOUT);
                org.tinysep.api.alert.Alert open = alertService.raise(new org.tinysep.api.alert.AlertRequest(
                        org.tinysep.api.alert.AlertKind.INACTIVITY, "browser-test", "", "Kitchen",
                        java.time.Instant.parse("2026-11-25T14:00:00Z"),
                        "TinySEP: no activity in Kitchen since 13:00", "Inactivity Recognition raised an alert."));
                browser.waitFor("document.getElementById('alert-service').textContent === 'Open alerts:'"
                        + " && document.querySelector('button.acknowledge') !== null"
                        + " && document.getElementById('inactivity-alert') !== null", WAIT, "the open alert with its button");
                browser.eval("(document.querySelector('button.acknowledge').click(), 1)");
                await(WAIT, () -> alertService.alert(open.id()).orElseThrow().state()
                        == org.tinysep.api.alert.AlertState.ACKNOWLEDGED, "the alert acknowledged from the page");
                browser.waitFor("document.querySelector('button.acknowledge') === null", WAIT,
                        "the acknowledged alert gone from the open ones");
                browser.eval("(document.querySelector('input[name=\"days\"][value=\"7\"]').click(), 1)");
                browser.waitFor("document.getElementById('timeline').dataset.slots === '84' && document.querySelectorAll('#timeline-svg rect.slot').length > 0",
                        WAIT, "the activity plot of the last 7 days");
                shot(browser, "caregiver");

                step = "no installer control for the caregiver";
                browser.eval("(document.getElementById('logout').click(), 1)");
                browser.waitFor("location.pathname === '/login.html' && document.readyState === 'complete'", WAIT, "the login page after logging out");
                browser.eval("(document.getElementById('user').value = 'caregiver', document.getElementById('password').value = "
                        + Chromium.quote(CAREGIVER_PASSWORD) + ", document.getElementById('submit').click(), 1)");
                browser.waitFor("location.pathname === '/caregiver.html' && document.readyState === 'complete'", WAIT, "the caregiver logged in");
                String shown = "(ids => ids.filter(id => document.getElementById(id).getClientRects().length > 0).join(','))";
                open(browser, base + "/drivers.html", "document.querySelectorAll('#applications tr').length > 0", "the drivers page as caregiver");
                assertEquals("installer controls the caregiver sees on the drivers page", "\"\"",
                        browser.eval(shown + "(['upload', 'jar', 'upload-button', 'reload'])"));
                assertEquals("0", browser.eval("document.querySelectorAll('#applications button').length"));
                open(browser, base + "/house.html", "document.querySelectorAll('#rooms tr').length > 0", "the house plan as caregiver");
                assertEquals("installer controls the caregiver sees on the house plan", "\"\"",
                        browser.eval(shown + "(['add-room', 'new-name', 'new-type', 'add'])"));
            } catch (AssertionError | RuntimeException e) {
                log.error("Browser test failed at '{}'; {}", step, browser.failureScreenshot("web-screenshots", step));
                throw e;
            }
        }
    }

    /** Logs the event log page's weight and time to first render (written to target/web-metrics.txt too). */
    private void metrics(Chromium browser) throws Exception {
        String json = browser.pageMetrics();
        log.info("Event log page: {}", json);
        System.out.println("WebBrowserTest: event log page (test flat): " + json);
        Files.createDirectories(Path.of("target"));
        Files.writeString(Path.of("target", "web-metrics.txt"), json + "\n");
        assertTrue(json, json.contains("\"firstContentfulPaintMs\":"));
    }

    /** Opens {@code url} in the browser and waits (at most {@link #WAIT}) until {@code ready}: the page shown. */
    private static void open(Chromium browser, String url, String ready, String what) throws Exception {
        browser.navigate(url);
        browser.waitFor(ready, WAIT, what);
    }

    /** A screenshot for looking at (target/ only: the pictures in docs/ come from WebDemoFlatTest's demo flat). */
    private void shot(Chromium browser, String page) throws Exception {
        browser.waitFor("document.readyState === 'complete'", WAIT, "the page loaded");
        browser.screenshot(Path.of("target", "web-screenshots", page + ".png").toAbsolutePath());
    }

    private String room(Login login, String name, String type) {
        HttpResponse<String> r = call("POST", "/api/rooms", "{\"name\":\"" + name + "\",\"type\":\"" + type + "\"}", login, true);
        assertEquals(r.body(), 200, r.statusCode());
        return field(r.body(), "uid");
    }

    private void put(Login login, String uid, String key, String value) {
        HttpResponse<String> r = call("PUT", "/api/devices/" + uid + "/parameters/" + key, "{\"value\":\"" + value + "\"}", login, true);
        assertEquals(r.body(), 200, r.statusCode());
    }

}

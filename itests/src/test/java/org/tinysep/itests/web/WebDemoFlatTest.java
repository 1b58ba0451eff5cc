package org.tinysep.itests.web;

import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.Option;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.LockStepTestSupport;
import org.tinysep.itests.demo.DemoFlat;
import org.tinysep.itests.TestSyncKey;
import org.tinysep.simulator.cli.Run;

/**
 * Every console page on the demo flat of {@code ./run.sh} (flat A, scenario demo-day, seed 1, played by the real
 * simulator in lock-step over UDP from 06:00 to 15:00, while Inactivity Recognition's bathroom alert is open), in
 * Debian's headless Chromium: each page is opened and waited on until it shows the flat, then photographed into
 * {@code target/web-demo-screenshots/}. With {@code -Dtinysep.web.screenshots=docs} (or the environment variable
 * {@code TINYSEP_WEB_SCREENSHOTS=docs}) the pictures also replace {@code docs/images/web-*.png}; CI never asks, so
 * it never rewrites files. Measures the event log page's weight and time to first render with the demo's history.
 * As in the distribution, the alert service and Sensor Health run: the bathroom alert has its Acknowledge button,
 * and the caregiver view lists the sensors in trouble: the Study's motion sensor, whose battery runs empty at 14:30
 * (a line added to demo-day: the Study is then unmonitored), and a window sensor in the Bathroom (node 1.21, sent by
 * the test) whose last keep-alive reported a low battery before it fell silent.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WebDemoFlatTest extends WebTestSupport {

    private static final Duration WAIT = Duration.ofSeconds(60);
    /** A window sensor the simulator does not play: it reports a low battery once, then falls silent. */
    private static final String DYING_NODE = "1.21";

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts", "org.tinysep.sensorhealth",
                "org.tinysep.sunspot.person", "org.tinysep.falldetection"); // Anna's pendant (issue 26)
    }

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.addAll(LockStepTestSupport.simulatorBundles());
        return o;
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>(super.initialConfigurations());
        LockStepTestSupport.putLockStepTime(configs);
        DemoFlat.configure(configs, "tinysep-web-demo-house-", DYING_NODE + "=Bathroom");
        configs.put("org.tinysep.sunspot.person", Map.of("persons", "0014.4F01.0000.0A04=Anna")); // as demo-flat.sh
        return configs;
    }


    /** demo-day with the Study's motion sensor's battery running empty at 14:30 (so the Study is unmonitored). */
    private static Path scenario() throws IOException {
        Path file = Files.createTempDirectory("tinysep-web-demo-scenario-").resolve("demo-day-battery.txt");
        String demo = Files.readString(DemoFlat.FLAT_A.resolve("..").resolve("..").resolve("scenarios").resolve("demo-day.txt"));
        Files.writeString(file, demo + "\n14:30 battery study-motion off    # the web console test: the Study unmonitored\n");
        return file;
    }


    private Path scenarioFile;

    private void simulate(ExecutorService executor, String from, String until) throws Exception {
        List<String> args = new ArrayList<>(List.of("--lockstep", "--amica-port", Integer.toString(udpPortOf("BusRadioAmicaUdp")),
                "--sunspot-port", Integer.toString(udpPortOf("BusRadioSunSpot")), "--sync-port", Integer.toString(syncPort()),
                "--sync-key", TestSyncKey.file().toString(), "--flat", "flat-a", "--scenario", scenarioFile.toString(), "--seed", "1",
                "--progress", "600", "--from", from, "--until", until));
        executor.submit(() -> {
            Run.simulate(args.toArray(new String[0]));
            return null;
        }).get(180, TimeUnit.SECONDS);
    }

    @Test
    public void everyPageShowsTheDemoFlat() throws Exception {
        setPasswords();
        String base = base();
        Login api = login("installer", INSTALLER_PASSWORD);
        ExecutorService executor = Executors.newSingleThreadExecutor();
        scenarioFile = scenario();
        try (AmicaNode dying = new AmicaNode(1, 21, udpPortOf("BusRadioAmicaUdp"), AmicaNodeType.WINDOW)) {
            simulate(executor, "06:00", "06:05");
            await(WAIT, () -> call("GET", "/api/devices", null, api, false).body().split("\"nodeAddress\":\"[0-9]").length > 20,
                    "flat A's AmICA devices");
            // handled at the next tick of the platform's (virtual) clock, i.e. once the simulation goes on
            dying.send(new KeepAlive(7200, 2150, 0x0A11, AmicaNodeType.productId(List.of(AmicaNodeType.WINDOW)), 4242));
            simulate(executor, "06:05", "15:00");
            await(WAIT, () -> call("GET", "/api/devices", null, api, false).body().contains("\"type\":\"AmicaWindow\"")
                    && call("GET", "/api/devices", null, api, false).body().contains("\"nodeAddress\":\"" + DYING_NODE + "\""),
                    "the window sensor of node " + DYING_NODE);
            await(WAIT, () -> call("GET", "/api/caregiver", null, api, false).body().contains("\"state\":\"ALERT\""),
                    "Inactivity Recognition's bathroom alert");
        } finally {
            executor.shutdownNow();
        }
        try (Chromium browser = Chromium.start(WAIT)) {
            String step = "login";
            try {
                browser.navigate(base + "/login.html");
                browser.waitFor("document.readyState === 'complete' && document.getElementById('submit') !== null", WAIT, "the login page");
                shot(browser, "login");
                browser.eval("(document.getElementById('password').value = " + Chromium.quote(INSTALLER_PASSWORD)
                        + ", document.getElementById('submit').click(), 1)");
                step = "event log";
                browser.waitFor("location.pathname === '/index.html' && performance.getEntriesByName('events-shown').length > 0"
                        + " && document.querySelectorAll('#events tr').length > 50", WAIT, "the event log with the demo day");
                metrics(browser);
                shot(browser, "events");
                step = "devices";
                page(browser, base, "devices.html", "document.querySelectorAll('#devices tr[data-uid]').length > 20", "the demo flat's devices");
                shot(browser, "devices");
                step = "device settings";
                browser.eval("(location.hash = Array.from(document.querySelectorAll('#devices tr[data-uid]'))"
                        + ".find(r => r.textContent.includes('AmicaDoor')).dataset.uid, 1)");
                browser.waitFor("document.getElementById('param-room') !== null && document.getElementById('param-kind') !== null", WAIT,
                        "a door's settings with the room and kind drop-downs");
                shot(browser, "device-settings");
                step = "connection graph";
                page(browser, base, "graph.html", "document.querySelectorAll('#graph .node').length > 20", "the demo flat's graph");
                shot(browser, "graph");
                step = "drivers";
                page(browser, base, "drivers.html", "document.querySelectorAll('#applications .driver').length > 10", "the drivers");
                shot(browser, "drivers");
                step = "house plan";
                page(browser, base, "house.html", "document.querySelectorAll('#rooms tr[data-uid]').length === 6"
                        + " && document.querySelectorAll('#plan-svg line').length > 4", "flat A's six rooms and their links");
                shot(browser, "house");
                step = "packet log";
                page(browser, base, "packets.html", "Array.from(document.querySelectorAll('#packets td.decoded')).filter(d => d.textContent).length > 20",
                        "decoded packets");
                shot(browser, "packets");
                step = "caregiver view";
                page(browser, base, "caregiver.html", "document.querySelectorAll('#timeline-svg rect.slot').length > 10"
                        + " && document.getElementById('inactivity-alert').textContent.includes('Bathroom')"
                        + " && document.querySelector('#alert-list button.acknowledge') !== null"
                        + " && Array.from(document.querySelectorAll('#sensor-problems li.unmonitored')).some(l => l.textContent"
                        + ".startsWith('The Study has no working motion sensor since '))"
                        + " && Array.from(document.querySelectorAll('#sensor-problems li.offline')).some(l => l.textContent"
                        + ".includes('(node 1.18) in the Study has been silent since'))"
                        + " && Array.from(document.querySelectorAll('#sensor-problems li.offline')).some(l => l.textContent"
                        + ".includes('(node " + DYING_NODE + ") in the Bathroom has been silent since'))"
                        + " && Array.from(document.querySelectorAll('#sensor-problems li.low-battery')).some(l => l.textContent"
                        + ".includes('(node " + DYING_NODE + ") in the Bathroom is low (2150 mV)'))",
                        "the activity plot, the open alert with its Acknowledge button, the sensors offline and the low battery");
                // issue 26: Anna's fall (her pendant) in words, and her pendant's last report and battery
                browser.waitFor("Array.from(document.querySelectorAll('#alert-list p[data-kind=FALL]')).some(p => p.textContent"
                        + ".startsWith('fall (the person may have fallen): Fall: Anna fell at 14:0'))"
                        + " && Array.from(document.querySelectorAll('#alert-list p.alert-explanation')).some(p => p.textContent"
                        + ".includes('last seen in the Bathroom at '))"
                        + " && Array.from(document.querySelectorAll('#person-nodes .person-node')).some(n => n.textContent"
                        + ".startsWith('Anna') && n.textContent.includes('Battery: not reported'))", WAIT,
                        "the FALL alert with its explanation and Anna's pendant");
                // issue 26 item 4: from Inactivity Recognition's persons(): her pendant is worn (it lay still only
                // after the fall, with no room activity since), she was last seen in the Bathroom, and her own watch
                // called for help after the Bathroom's limit
                browser.waitFor("Array.from(document.querySelectorAll('#person-nodes .person-node')).some(n => "
                        + "n.querySelector('.worn').textContent === \"Worn: yes: its movement counts as Anna's activity\""
                        + " && n.querySelector('.last-movement').textContent.startsWith('Last movement: ')"
                        + " && n.querySelector('.last-room').textContent === 'Last room: last seen in the Bathroom'"
                        + " && n.querySelector('.person-watch').textContent.startsWith('Watch: ALERT: Anna has not been "
                        + "active for longer than the limit of the Bathroom'))"
                        + " && !document.getElementById('person-nodes').textContent.includes('not known here yet')", WAIT,
                        "Anna's pendant worn, last seen in the Bathroom, her own watch in ALERT");
                shot(browser, "caregiver", 1250); // the alerts and the sensors below the cards
            } catch (AssertionError | RuntimeException e) {
                log.error("Demo flat browser test failed at '{}'; {}", step, browser.failureScreenshot("web-demo-screenshots", step));
                throw e;
            }
        }
    }

    private static void page(Chromium browser, String base, String page, String condition, String what) throws InterruptedException {
        browser.navigate(base + "/" + page);
        browser.waitFor("location.pathname === '/" + page + "' && document.readyState === 'complete' && (" + condition + ")", WAIT, what);
    }

    /** The event log page with the demo day's history: weight and time to first render, printed. */
    private void metrics(Chromium browser) {
        String json = browser.pageMetrics();
        System.out.println("WebDemoFlatTest: event log page (demo flat): " + json);
        log.info("Event log page on the demo flat: {}", json);
        assertTrue(json, json.contains("\"firstContentfulPaintMs\":"));
    }

    private void shot(Chromium browser, String page) throws Exception {
        shot(browser, page, 0);
    }

    /** @param height 0: the window; else the page's top that many pixels (at most) */
    private void shot(Chromium browser, String page, int height) throws Exception {
        browser.waitFor("document.readyState === 'complete'", WAIT, "the page loaded");
        Path file = Path.of("target", "web-demo-screenshots", page + ".png").toAbsolutePath();
        if (height > 0) {
            browser.screenshot(file, height);
        } else {
            browser.screenshot(file);
        }
        String wanted = System.getProperty("tinysep.web.screenshots", "");
        if (!wanted.equals("docs")) {
            wanted = System.getenv().getOrDefault("TINYSEP_WEB_SCREENSHOTS", "");
        }
        String docs = System.getProperty("tinysep.docs.images", "");
        if (wanted.equals("docs") && !docs.isEmpty() && !docs.startsWith("${")) {
            Files.copy(file, Path.of(docs, "web-" + page + ".png"), StandardCopyOption.REPLACE_EXISTING);
        }
    }
}

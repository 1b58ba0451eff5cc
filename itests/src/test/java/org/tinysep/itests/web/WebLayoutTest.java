package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.Option;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.itests.AmicaNode;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/**
 * The console's layout measured in a real browser (headless Chromium, issue 32 item 6): in the devices table no
 * cell breaks a line inside a word (it did: {@code BusRadioA|micaUdp}, when long OFFLINE details squeezed the other
 * columns), and in the connections graph every device's name is shown whole and no label leaves its box (Sun SPOT
 * names were cut off). The table check proves it can fail: with the old rule ({@code overflow-wrap: anywhere})
 * injected into the same page, it finds the words broken.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WebLayoutTest extends WebTestSupport {

    private static final Duration WAIT = Duration.ofSeconds(30);

    /**
     * The words (runs of letters and digits) of the devices table that a line break cuts in two; a break after a
     * hyphen, a dot or a space is a break between words.
     */
    private static final String BROKEN_WORDS = "(() => { const broken = [];"
            + " const w = document.createTreeWalker(document.getElementById('devices'), NodeFilter.SHOW_TEXT);"
            + " for (let n = w.nextNode(); n; n = w.nextNode()) for (const m of n.data.matchAll(/[A-Za-z0-9]+/g)) {"
            + "   const r = document.createRange(); r.setStart(n, m.index); r.setEnd(n, m.index + m[0].length);"
            + "   const tops = new Set(Array.from(r.getClientRects()).filter(x => x.width > 0).map(x => Math.round(x.top)));"
            + "   if (tops.size > 1) broken.push(m[0]); }"
            + " return broken.join(' '); })()";

    /**
     * Each graph box whose first label is not the device's whole name (its tooltip begins {@code <name> — }), or one
     * of whose labels leaves the box.
     */
    private static final String CLIPPED_LABELS = "(() => { const bad = [];"
            + " for (const a of document.querySelectorAll('#graph a.node')) {"
            + "   const name = a.querySelector('title').textContent.split(' \u2014 ')[0];"
            + "   const box = a.querySelector('rect').getBBox(); const texts = a.querySelectorAll('text');"
            + "   if (texts[0].textContent !== name) bad.push('cut: ' + texts[0].textContent);"
            + "   for (const t of texts) { const b = t.getBBox();"
            + "     if (b.x < box.x || b.x + b.width > box.x + box.width) bad.push('outside its box: ' + t.textContent); } }"
            + " return bad.join(' | '); })()";

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.addAll(sunSpotBundles(5));
        return o;
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        // AmICA nodes OFFLINE after 2 missed reports: long status details, as after the demo day
        return replacing(super.initialConfigurations(), UDP_PID,
                Map.of("port", "0", "bindAddress", "127.0.0.1", "silentAfterIntervals", "2"));
    }

    private static void sunSpot(DatagramSocket socket, int port, String address, SunSpotPayload payload)
            throws Exception {
        byte[] frame = SunSpotCodec.encode(new SunSpotFrame(SunSpotAddress.parse(address), payload.sensorType().code(),
                SunSpotPayloads.encode(payload)));
        socket.send(new DatagramPacket(frame, frame.length, new InetSocketAddress(InetAddress.getLoopbackAddress(), port)));
    }

    @Test
    public void noCellBreaksInsideAWordAndNoGraphLabelIsClipped() throws Exception {
        setPasswords();
        String base = base();
        Login api = login("installer", INSTALLER_PASSWORD);
        List<AmicaNode> nodes = new ArrayList<>();
        try (DatagramSocket spots = new DatagramSocket(0, InetAddress.getLoopbackAddress());
                Chromium browser = Chromium.start(WAIT)) {
            nodes.add(awakeNode(1, 20, AmicaNodeType.DOOR));
            nodes.add(awakeNode(1, 17, AmicaNodeType.MOVEMENT));
            AmicaNode light = awakeNode(1, 30, AmicaNodeType.SIMPLE_LIGHT);
            nodes.add(light);
            light.send(new LightControl(0));
            int spotPort = udpPortOf("BusRadioSunSpot");
            sunSpot(spots, spotPort, "0014.4F01.0000.0102", new MovementDetection(false));
            sunSpot(spots, spotPort, "0014.4F01.0000.0103", new TemperatureStatus(21.5));
            awaitDevice(api, "AmicaDoor", "1.20");
            awaitDevice(api, "AmicaMovement", "1.17");
            awaitDevice(api, "SunSpotMovement", "0014.4F01.0000.0102");
            awaitDevice(api, "SunSpotTemperature", "0014.4F01.0000.0103");
            // the door node falls silent: it and its door are OFFLINE with long details
            await(WAIT, () -> call("GET", "/api/devices", null, api, false).body()
                    .contains("its radio node 1.20 has been silent since"), "the door OFFLINE with its node");

            browser.navigate(base + "/login.html");
            browser.waitFor("document.readyState === 'complete' && document.getElementById('submit') !== null", WAIT,
                    "the login page");
            browser.eval("(document.getElementById('password').value = " + Chromium.quote(INSTALLER_PASSWORD)
                    + ", document.getElementById('submit').click(), 1)");
            browser.waitFor("location.pathname === '/index.html'", WAIT, "logged in");

            browser.navigate(base + "/devices.html");
            browser.waitFor("document.querySelectorAll('#devices tr[data-uid]').length >= 10"
                    + " && document.getElementById('devices').textContent.includes('has been silent since')", WAIT,
                    "the devices table with an OFFLINE detail");
            String widths = "('main ' + document.querySelector('main').clientWidth + ', table '"
                    + " + document.querySelector('#devices-box table').offsetWidth + ', td overflow-wrap '"
                    + " + getComputedStyle(document.querySelector('#devices td')).overflowWrap)";
            log.info("Devices table at 1280 px: {}", browser.eval(widths));
            assertEquals("words broken inside the devices table at 1280 px", "\"\"", browser.eval(BROKEN_WORDS));
            // a small laptop's width (main about 770 px beside the live panel): the columns must share little room
            browser.command("Emulation.setDeviceMetricsOverride",
                    "{\"width\":1100,\"height\":860,\"deviceScaleFactor\":1,\"mobile\":false}");
            log.info("Devices table at 1100 px (new rule): {}", browser.eval(widths));
            String broken = browser.eval(BROKEN_WORDS);
            browser.screenshot(java.nio.file.Path.of("target", "web-screenshots", "layout-devices.png"));
            assertEquals("words broken inside the devices table", "\"\"", broken);
            // the measurement catches the old rule: the same page with overflow-wrap: anywhere breaks words
            // (through the CSS object model: the console's Content-Security-Policy refuses a <style> element)
            browser.eval("(s => s.insertRule('td { overflow-wrap: anywhere !important; }', s.cssRules.length))"
                    + "(Array.from(document.styleSheets).find(s => s.href && s.href.endsWith('/console.css')))");
            log.info("Devices table (old rule): {}", browser.eval(widths));
            String old = browser.eval(BROKEN_WORDS);
            assertFalse("the old rule must break some word here, else this layout proves nothing", old.equals("\"\""));
            log.info("With the old rule, words broken: {}", old);

            browser.navigate(base + "/graph.html");
            browser.waitFor("document.querySelectorAll('#graph a.node').length >= 10", WAIT, "the connections graph");
            String names = browser.eval("Array.from(document.querySelectorAll('#graph a.node text:first-of-type'))"
                    + ".map(t => t.textContent).join('|')");
            assertTrue(names, names.contains("Sun SPOT 0014.4F01.0000.0102"));
            browser.screenshot(java.nio.file.Path.of("target", "web-screenshots", "layout-graph.png"));
            assertEquals("graph labels cut or outside their box", "\"\"", browser.eval(CLIPPED_LABELS));
        } finally {
            nodes.forEach(AmicaNode::close);
        }
    }
}

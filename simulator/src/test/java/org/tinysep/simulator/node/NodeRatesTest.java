package org.tinysep.simulator.node;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;

/** Counts the frames of flat A's nodes over one virtual minute, decoded with the protocol libraries. */
class NodeRatesTest extends NodeTestSupport {

    private static final int AMICA_TOTAL = 20 + 6 * 30 + 30 + 4 * 60 + 9 * 6;

    @Test
    void aVirtualMinuteHasTheThesisRates() throws Exception {
        for (long t = T0; t < T0 + 60; t++) {
            nodes.tick(t);
        }
        List<Radio.Datagram> in = amica.await(d -> true, AMICA_TOTAL);
        Map<String, Integer> c = amicaCounts(in);
        assertEquals(AMICA_TOTAL, in.size(), c.toString());
        for (int a = 1; a <= 20; a++) {
            assertEquals(1, c.get("1." + a + " KeepAlive"), "keep-alive of 1." + a + ": " + c);
        }
        assertEquals(30, c.get("1.1 MotionDetection"));
        assertEquals(30, c.get("1.20 MotionDetection"), "pet collar");
        assertEquals(60, c.get("1.3 ReedSwitchStatus"), "outer door");
        assertEquals(60, c.get("1.6 ReedSwitchStatus"), "window");
        assertEquals(6, c.get("1.5 LightControl"));
        assertEquals(6, c.get("1.7 HeaterControl"));
        assertEquals(6, c.get("1.8 SpeakerControl"));

        Map<String, Integer> s = sunSpotCounts(spots.await(d -> true, 42));
        assertEquals(Map.of("0014.4F01.0000.0A01 MovementDetection", 30, "0014.4F01.0000.0A02 TemperatureStatus", 6,
                "0014.4F01.0000.0A03 LightStatus", 6), s);
    }

    @Test
    void sensorsReportWhatTheEnvironmentShows() throws Exception {
        for (long t = T0; t < T0 + 10; t++) {
            nodes.tick(t);
        }
        int living = 0;
        int kitchen = 0;
        int open = 0;
        for (Radio.Datagram d : amica.await(d -> true, 20 + 6 * 5 + 5 + 4 * 10 + 9)) {
            AmicaFrame f = amicaFrame(d);
            AmicaPayload p = AmicaPayloads.decode(f.payload());
            String from = f.sender().toString();
            if (p instanceof MotionDetection m && from.equals("1.4") && m.detected()) {
                living++;
            } else if (p instanceof MotionDetection m && from.equals("1.9") && m.detected()) {
                kitchen++;
            } else if (p instanceof ReedSwitchStatus r && r.open()) {
                assertEquals("1.3", from, "only the outer door opens");
                open++;
            } else if (p instanceof HeaterControl h && from.equals("1.7")) {
                assertEquals(40, h.percent(), "initial percent=40 from nodes.txt");
            } else if (p instanceof KeepAlive k) {
                assertEquals(0, k.uptimeSeconds());
                assertEquals(3000, k.batteryMillivolts());
            }
        }
        assertEquals(5, living);
        assertEquals(0, kitchen);
        assertEquals(5, open, "open at even seconds");
    }

    @Test
    void everyAmicaNodeHasItsOwnSocket() throws Exception {
        nodes.tick(T0);
        // every node's keep-alive of the first second (other frames of that second may come first: awaiting any
        // 20 datagrams once saw 19 senders)
        List<Radio.Datagram> in = amica.await(d -> isKeepAlive(d), 20).stream().filter(d -> isKeepAlive(d))
                .toList();
        Map<String, Integer> ports = new java.util.HashMap<>();
        for (Radio.Datagram d : in) {
            ports.put(amicaFrame(d).sender().toString(), d.from().getPort());
        }
        assertEquals(20, ports.size());
        assertEquals(20, ports.values().stream().distinct().count());
        assertTrue(in.stream().allMatch(d -> d.from().getAddress().isLoopbackAddress()));
    }

    private static boolean isKeepAlive(Radio.Datagram d) {
        try {
            return AmicaPayloads.decode(amicaFrame(d).payload()) instanceof KeepAlive;
        } catch (org.tinysep.amica.protocol.AmicaProtocolException e) {
            throw new AssertionError("a frame the nodes sent does not decode: " + e.getMessage(), e);
        }
    }
}

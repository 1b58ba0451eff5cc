package org.tinysep.simulator.node;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetSocketAddress;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/** Commands from the (stand-in) bus radio change a node's state, which it reports at once and in later statuses. */
class ActuatorTest extends NodeTestSupport {

    private final java.util.Map<String, InetSocketAddress> ports = new java.util.HashMap<>();

    private InetSocketAddress portOf(String address) throws Exception {
        InetSocketAddress known = ports.get(address);
        if (known != null) {
            return known;
        }
        InetSocketAddress a = amica.await(d -> amicaFrame(d).sender().toString().equals(address), 1).stream()
                .filter(d -> amicaFrame(d).sender().toString().equals(address)).findFirst().orElseThrow().from();
        ports.put(address, a);
        return a;
    }

    private void command(String address, AmicaPayload p) throws Exception {
        byte[] b = AmicaCodec.encode(AmicaFrame.fromPlatform(AmicaAddress.parse(address), 9, AmicaPayloads.encode(p)));
        amica.send(b, portOf(address));
    }

    private static boolean is(Radio.Datagram d, String from, AmicaPayload p) {
        try {
            AmicaFrame f = amicaFrame(d);
            return f.sender().toString().equals(from) && AmicaPayloads.decode(f.payload()).equals(p);
        } catch (Exception e) {
            return false;
        }
    }

    @Test
    void aLightCommandChangesTheLightWhichReportsAtOnceAndLater() throws Exception {
        nodes.tick(T0);
        command("1.16", new LightControl(40));
        List<Radio.Datagram> in = amica.await(d -> is(d, "1.16", new LightControl(40)), 1);
        assertTrue(in.stream().anyMatch(d -> is(d, "1.16", new LightControl(40))), "immediate status");
        assertTrue(events.contains("bedroom-light light 40 %"), events.toString());

        amica.clear();
        spots.clear();
        nodes.tick(T0 + 10);
        in = amica.await(d -> is(d, "1.16", new LightControl(40)), 1);
        assertTrue(in.stream().anyMatch(d -> is(d, "1.16", new LightControl(40))), "periodic status");
        assertTrue(spots.await(d -> true, 3).stream().anyMatch(d -> {
            try {
                return SunSpotPayloads.decode(SunSpotCodec.decode(d.bytes(), 0, d.bytes().length).payload())
                        .equals(new LightStatus(40));
            } catch (Exception e) {
                return false;
            }
        }), "the bedroom's Sun SPOT light sensor sees the lamp");
    }

    @Test
    void heaterCommandsWorkAndOtherCommandsAreIgnoredNotFatal() throws Exception {
        nodes.tick(T0);
        amica.send(new byte[] {1, 2, 3}, portOf("1.14"));
        command("1.1", new LightControl(100));
        command("1.14", new HeaterControl(75));
        amica.await(d -> is(d, "1.14", new HeaterControl(75)), 1);
        assertTrue(amica.received().stream().anyMatch(d -> is(d, "1.14", new HeaterControl(75))));
        long end = System.currentTimeMillis() + 5000;
        while (events.stream().noneMatch(e -> e.startsWith("hall-motion ignored a command")) && System.currentTimeMillis() < end) {
            Thread.sleep(10);
        }
        assertTrue(events.stream().anyMatch(e -> e.startsWith("hall-motion ignored a command")), events.toString());
    }

    @Test
    void anEmptyBatterySilencesTheNodeUntilItIsOnAgain() throws Exception {
        nodes.tick(T0);
        portOf("1.5");
        nodes.power("living-light", false);
        nodes.power("living-motion", false);
        nodes.power("no-such-node", false);
        amica.clear();
        command("1.5", new LightControl(70));
        for (long t = T0 + 1; t < T0 + 20; t++) {
            nodes.tick(t);
        }
        command("1.16", new LightControl(10));
        List<Radio.Datagram> in = amica.await(d -> is(d, "1.16", new LightControl(10)), 1);
        assertFalse(in.stream().anyMatch(d -> List.of("1.4", "1.5").contains(amicaFrame(d).sender().toString())),
                "switched-off nodes are silent");

        amica.clear();
        nodes.power("living-motion", true);
        nodes.power("living-light", true);
        nodes.tick(T0 + 20);
        in = amica.await(d -> amicaFrame(d).sender().toString().equals("1.4"), 2);
        AmicaPayload first = in.stream().filter(d -> amicaFrame(d).sender().toString().equals("1.4"))
                .map(d -> decode(d)).findFirst().orElseThrow();
        assertEquals(0, ((KeepAlive) first).uptimeSeconds(), "starts up anew with a keep-alive");
        assertTrue(amica.await(d -> is(d, "1.5", new LightControl(0)), 1).stream().anyMatch(d -> is(d, "1.5", new LightControl(0))),
                "the command sent while off was not carried out");
    }

    private static AmicaPayload decode(Radio.Datagram d) {
        try {
            return AmicaPayloads.decode(amicaFrame(d).payload());
        } catch (Exception e) {
            throw new AssertionError(e);
        }
    }
}

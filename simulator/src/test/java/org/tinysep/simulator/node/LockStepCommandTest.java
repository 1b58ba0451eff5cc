package org.tinysep.simulator.node;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.simulator.flat.FlatLoader;

/**
 * Issue 17: in lock-step a node carries out a command only at the start of the next virtual second, on the
 * simulation's thread (never when a receive thread happens to run), and its answer counts as a change, so the
 * lock-step paces it like any other before the TICK.
 */
class LockStepCommandTest extends NodeTestSupport {

    @Test
    void aCommandIsCarriedOutAtTheStartOfTheNextSecondAndItsAnswerCountsAsAChange() throws Exception {
        nodes.close();
        nodes = NodeFactory.create(FlatLoader.load("flat-a"), env,
                new Target(InetAddress.getLoopbackAddress(), amica.port(), spots.port()), events::add, true);
        nodes.tick(T0);
        InetSocketAddress bedroomLight = amica.await(d -> from(d, "1.16"), 1).stream().filter(d -> from(d, "1.16"))
                .findFirst().orElseThrow().from();
        // odd seconds after start-up: only the reed switches change (the door stands open at even seconds)
        int first = nodes.tick(T0 + 1);
        nodes.tick(T0 + 2);
        int before = nodes.tick(T0 + 3);
        nodes.tick(T0 + 4);
        assertEquals(first, before, "odd seconds change alike");

        amica.clear();
        byte[] command = AmicaCodec.encode(AmicaFrame.fromPlatform(AmicaAddress.parse("1.16"), 9,
                AmicaPayloads.encode(new LightControl(40))));
        amica.send(command, bedroomLight);
        Thread.sleep(300); // what a receive thread of its own would need to answer at once
        assertFalse(amica.received().stream().anyMatch(d -> answer(d)), "nothing carried out between seconds");
        assertFalse(events.contains("bedroom-light light 40 %"), events.toString());

        assertEquals(before + 1, nodes.tick(T0 + 5), "the answer is one more change than in the odd second before");
        assertTrue(events.contains("bedroom-light light 40 %"), events.toString());
        List<Radio.Datagram> in = amica.await(d -> answer(d), 1);
        assertTrue(in.stream().anyMatch(d -> answer(d)), "the answer went out in that second");
    }

    private static boolean from(Radio.Datagram d, String node) {
        return amicaFrame(d).sender().toString().equals(node);
    }

    private static boolean answer(Radio.Datagram d) {
        try {
            return from(d, "1.16") && AmicaPayloads.decode(amicaFrame(d).payload()).equals(new LightControl(40));
        } catch (Exception e) {
            return false;
        }
    }
}

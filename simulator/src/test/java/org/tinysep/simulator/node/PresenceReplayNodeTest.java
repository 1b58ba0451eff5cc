package org.tinysep.simulator.node;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.net.InetAddress;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.simulator.replay.NodeSpec;
import org.tinysep.simulator.replay.Signal;

/** A replayed seat mat over real UDP: its keep-alive announces bit 9, its state goes out as Reed-Switch Status. */
class PresenceReplayNodeTest {

    @Test
    void aSeatMatNodeAnnouncesItsPresenceBitAndSendsReedSwitchStatus() throws Exception {
        try (Radio radio = new Radio(); ReplayNodes nodes = ReplayNodes.create(List.of(new NodeSpec("Seat", "amica",
                new AmicaAddress(1, 40), AmicaNodeType.PRESENCE_SEAT, "Living Room", "", "Seat (Pressure)")),
                new Target(InetAddress.getLoopbackAddress(), radio.port(), 1), false)) {
            nodes.tick(0);
            nodes.node("Seat").enter(Signal.CONTACT_OPEN);
            List<AmicaPayload> got = payloads(radio.await(d -> true, 2));
            KeepAlive ka = (KeepAlive) got.get(0);
            assertEquals(0x0200, ka.productId());
            assertEquals(Set.of(AmicaNodeType.PRESENCE_SEAT), ka.nodeTypes());
            assertEquals(new ReedSwitchStatus(true), got.get(1), "ON");
            assertEquals(1, nodes.node("Seat").period(), "repeats like a reed switch at the full rate");
        }
    }

    private static List<AmicaPayload> payloads(List<Radio.Datagram> in) throws Exception {
        List<AmicaPayload> out = new java.util.ArrayList<>();
        for (Radio.Datagram d : in) {
            out.add(AmicaPayloads.decode(NodeTestSupport.amicaFrame(d).payload()));
        }
        return out;
    }
}

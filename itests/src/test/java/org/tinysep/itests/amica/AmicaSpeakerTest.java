package org.tinysep.itests.amica;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.SPEAKER;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.tinysep.amica.protocol.SpeakerControl;
import org.tinysep.api.actuator.SpeakerProvider;
import org.tinysep.api.device.Device;
import org.tinysep.api.sensor.Percent;
import org.tinysep.itests.AmicaNode;

/**
 * AmICA Speaker in a real framework over real UDP: Speaker Control status in, volume out; setVolume puts
 * 5 4 0 A on the node's socket; the node's next status confirms.
 */
public class AmicaSpeakerTest extends AmicaTestSupport {

    @Test
    public void aSpeakerNodeIsSetAndConfirmsByItsNextStatus() throws Exception {
        try (AmicaNode node = node(1, 22, SPEAKER)) {
            SpeakerProvider provider = announce(node, "AmicaSpeaker", SpeakerProvider.class, "speaker");
            Device device = device("AmicaSpeaker", node.id());
            List<Percent> heard = new CopyOnWriteArrayList<>();
            provider.connect((source, value, at) -> heard.add(value));

            node.send(new SpeakerControl(10));
            node.send(new SpeakerControl(10)); // repeated every 10 s by the node: not a change
            node.send(new SpeakerControl(25));
            awaitEquals("status reports", List.of(Percent.of(10), Percent.of(25)), () -> List.copyOf(heard));

            provider.setVolume(Percent.of(40));
            expectCommand(node, 5, 4, 0, 40);
            assertEquals("unchanged before the node confirms", Optional.of(Percent.of(25)), provider.volume());
            assertEquals("40%", parameter(device, "pending"));
            node.send(new SpeakerControl(40));
            awaitEquals("confirmed", List.of(Percent.of(10), Percent.of(25), Percent.of(40)), () -> List.copyOf(heard));
            assertEquals(Optional.of(Percent.of(40)), provider.volume());
            assertEquals("", parameter(device, "pending"));

            shell("tinysep:set " + device.uid() + " volume 70");
            expectCommand(node, 5, 4, 0, 70);
            assertEquals("70%", parameter(device, "pending"));
            node.send(new SpeakerControl(70));
            awaitEquals("volume parameter", "70%", () -> parameter(device, "volume"));
        }
    }
}

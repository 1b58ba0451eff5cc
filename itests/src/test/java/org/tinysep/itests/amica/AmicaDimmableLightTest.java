package org.tinysep.itests.amica;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.DIMMABLE_LIGHT;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.device.Device;
import org.tinysep.api.sensor.Percent;
import org.tinysep.itests.AmicaNode;

/**
 * AmICA Dimmable Light in a real framework over real UDP: Light Control status in, brightness out; setBrightness puts
 * 5 2 0 A on the node's socket; the node's next status confirms.
 */
public class AmicaDimmableLightTest extends AmicaTestSupport {

    @Test
    public void aDimmableLightNodeIsSetAndConfirmsByItsNextStatus() throws Exception {
        try (AmicaNode node = node(1, 20, DIMMABLE_LIGHT)) {
            DimmableLightProvider provider = announce(node, "AmicaDimmableLight", DimmableLightProvider.class, "dimmable-light");
            Device device = device("AmicaDimmableLight", node.id());
            List<Percent> heard = new CopyOnWriteArrayList<>();
            provider.connect((source, value, at) -> heard.add(value));

            node.send(new LightControl(10));
            node.send(new LightControl(10)); // repeated every 10 s by the node: not a change
            node.send(new LightControl(25));
            awaitEquals("status reports", List.of(Percent.of(10), Percent.of(25)), () -> List.copyOf(heard));

            provider.setBrightness(Percent.of(40));
            expectCommand(node, 5, 2, 0, 40);
            assertEquals("unchanged before the node confirms", Optional.of(Percent.of(25)), provider.brightness());
            assertEquals("40%", parameter(device, "pending"));
            node.send(new LightControl(40));
            awaitEquals("confirmed", List.of(Percent.of(10), Percent.of(25), Percent.of(40)), () -> List.copyOf(heard));
            assertEquals(Optional.of(Percent.of(40)), provider.brightness());
            assertEquals("", parameter(device, "pending"));

            shell("tinysep:set " + device.uid() + " brightness 70");
            expectCommand(node, 5, 2, 0, 70);
            assertEquals("70%", parameter(device, "pending"));
            node.send(new LightControl(70));
            awaitEquals("brightness parameter", "70%", () -> parameter(device, "brightness"));
        }
    }
}

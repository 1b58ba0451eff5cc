package org.tinysep.itests.amica;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.HEATER;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.api.actuator.HeaterProvider;
import org.tinysep.api.device.Device;
import org.tinysep.api.sensor.Percent;
import org.tinysep.itests.AmicaNode;

/**
 * AmICA Heater in a real framework over real UDP: Heater Control status in, potency out; setPotency puts
 * 5 8 0 A on the node's socket; the node's next status confirms.
 */
public class AmicaHeaterTest extends AmicaTestSupport {

    @Test
    public void aHeaterNodeIsSetAndConfirmsByItsNextStatus() throws Exception {
        try (AmicaNode node = node(1, 21, HEATER)) {
            HeaterProvider provider = announce(node, "AmicaHeater", HeaterProvider.class, "heater");
            Device device = device("AmicaHeater", node.id());
            List<Percent> heard = new CopyOnWriteArrayList<>();
            provider.connect((source, value, at) -> heard.add(value));

            node.send(new HeaterControl(10));
            node.send(new HeaterControl(10)); // repeated every 10 s by the node: not a change
            node.send(new HeaterControl(25));
            awaitEquals("status reports", List.of(Percent.of(10), Percent.of(25)), () -> List.copyOf(heard));

            provider.setPotency(Percent.of(40));
            expectCommand(node, 5, 8, 0, 40);
            assertEquals("unchanged before the node confirms", Optional.of(Percent.of(25)), provider.potency());
            assertEquals("40%", parameter(device, "pending"));
            node.send(new HeaterControl(40));
            awaitEquals("confirmed", List.of(Percent.of(10), Percent.of(25), Percent.of(40)), () -> List.copyOf(heard));
            assertEquals(Optional.of(Percent.of(40)), provider.potency());
            assertEquals("", parameter(device, "pending"));

            shell("tinysep:set " + device.uid() + " potency 70");
            expectCommand(node, 5, 8, 0, 70);
            assertEquals("70%", parameter(device, "pending"));
            node.send(new HeaterControl(70));
            awaitEquals("potency parameter", "70%", () -> parameter(device, "potency"));
        }
    }
}

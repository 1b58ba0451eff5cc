package org.tinysep.itests.amica;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.SIMPLE_LIGHT;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.Device;
import org.tinysep.itests.AmicaNode;

/**
 * AmICA Simple Light in a real framework over real UDP: status in, on/off out; switching through the provider and
 * through {@code tinysep:set} puts the exact Light Control bytes on the node's socket; the node's next status
 * confirms.
 */
public class AmicaSimpleLightTest extends AmicaTestSupport {

    @Test
    public void aLightNodeIsSwitchedAndConfirmsByItsNextStatus() throws Exception {
        try (AmicaNode node = node(1, 30, SIMPLE_LIGHT)) {
            SimpleLightProvider light = announce(node, "AmicaSimpleLight", SimpleLightProvider.class, "simple-light");
            Device device = device("AmicaSimpleLight", node.id());
            List<Boolean> heard = new CopyOnWriteArrayList<>();
            light.connect((source, on, at) -> heard.add(on));

            node.send(new LightControl(0));
            awaitEquals("first status", List.of(false), () -> List.copyOf(heard));

            light.switchLight(true);
            expectCommand(node, 5, 2, 0, 100);
            assertEquals("not on before the node confirms", Optional.of(false), light.isOn());
            assertEquals("true", parameter(device, "pending"));
            node.send(new LightControl(100));
            awaitEquals("confirmed on", List.of(false, true), () -> List.copyOf(heard));
            assertEquals(Optional.of(true), light.isOn());
            assertEquals("", parameter(device, "pending"));

            shell("tinysep:set " + device.uid() + " on false");
            expectCommand(node, 5, 2, 0, 0);
            assertEquals("false", parameter(device, "pending"));
            assertEquals("true", parameter(device, "on"));
            node.send(new LightControl(0));
            awaitEquals("confirmed off", List.of(false, true, false), () -> List.copyOf(heard));
            assertEquals("false", parameter(device, "on"));
        }
    }
}

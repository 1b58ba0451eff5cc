package org.tinysep.itests.amica;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.WINDOW;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.device.Device;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.WindowListener;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.itests.AmicaNode;

/** AmICA Window in a real framework over real UDP: keep-alive, reed-switch changes, the position parameter. */
public class AmicaWindowTest extends AmicaTestSupport {

    @Test
    public void aWindowNodeBecomesAWindowWhoseChangesReachItsListeners() throws Exception {
        try (AmicaNode node = node(1, 21, WINDOW)) {
            WindowProvider window = announce(node, "AmicaWindow", WindowProvider.class, "window");
            assertEquals(OpenState.UNKNOWN, window.state());

            List<String> heard = new CopyOnWriteArrayList<>();
            window.connect(new WindowListener() {
                @Override
                public void windowChanged(WindowProvider source, OpenState state, java.time.Instant at) {
                    heard.add(state.name());
                }

                @Override
                public void windowPositionChanged(WindowProvider source, Coordinates position,
                        java.time.Instant at) {
                    heard.add("position " + position.x() + "," + position.y() + "," + position.z());
                }
            });
            node.send(new ReedSwitchStatus(true));
            node.send(new ReedSwitchStatus(true)); // repeated every second by the node: not a change
            node.send(new ReedSwitchStatus(false));
            awaitEquals("window changes", List.of("OPEN", "CLOSED"), () -> List.copyOf(heard));
            assertEquals(OpenState.CLOSED, window.state());

            Device device = device("AmicaWindow", node.id());
            shell("tinysep:set " + device.uid() + " position 2.5,0,1.2");
            awaitEquals("position event", List.of("OPEN", "CLOSED", "position 2.5,0.0,1.2"), () -> List.copyOf(heard));
            assertEquals(Optional.of(new Coordinates(2.5, 0, 1.2)), window.position());
            assertEquals("2.5,0.0,1.2", parameter(device, "position"));
        }
    }
}

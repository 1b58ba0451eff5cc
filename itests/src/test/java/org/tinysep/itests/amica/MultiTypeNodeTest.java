package org.tinysep.itests.amica;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;
import static org.tinysep.amica.protocol.AmicaNodeType.SIMPLE_LIGHT;

import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.itests.AmicaNode;

/**
 * Thesis 3.9.1: "one AmICA sensor node can be of several types". A motion-activated lamp announces movement +
 * simple-light in one keep-alive: exactly one abstraction device per type appears (none of the other AmICA
 * abstractions attaches), each provider carries its own type only, and each hears only its own payloads.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class MultiTypeNodeTest extends AmicaTestSupport {

    @Test
    public void aMovementAndLightNodeYieldsOneDevicePerType() throws Exception {
        try (AmicaNode node = node(1, 40, MOVEMENT, SIMPLE_LIGHT)) {
            node.keepAlive();
            device("AmicaMovement", node.id());
            device("AmicaSimpleLight", node.id());
            awaitEquals("devices at " + node.id(), Set.of(BUS, "AmicaMovement", "AmicaSimpleLight"),
                    () -> deviceTypesAt(node.id()));
            assertEquals(List.of("movement"), providerNodeTypes(MovementProvider.class, node.id()));
            assertEquals(List.of("simple-light"), providerNodeTypes(SimpleLightProvider.class, node.id()));

            List<String> heard = new CopyOnWriteArrayList<>();
            provider(MovementProvider.class, node.id()).connect((src, m) -> heard.add("motion " + m.detected()));
            SimpleLightProvider light = provider(SimpleLightProvider.class, node.id());
            light.connect((src, on, at) -> heard.add("light " + on));

            node.send(new MotionDetection(true));
            node.send(new LightControl(100));
            awaitEquals("each payload reaches its own abstraction only", List.of("motion true", "light true"),
                    () -> List.copyOf(heard));

            light.switchLight(false);
            expectCommand(node, 5, 2, 0, 0);
            node.send(new LightControl(0));
            node.send(new MotionDetection(false));
            awaitEquals("after the command", List.of("motion true", "light true", "light false", "motion false"),
                    () -> List.copyOf(heard));
            assertEquals("still one device per type", Set.of(BUS, "AmicaMovement", "AmicaSimpleLight"),
                    deviceTypesAt(node.id()));
        }
    }
}

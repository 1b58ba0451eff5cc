package org.tinysep.itests.amica;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.PET_COLLAR;

import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.itests.AmicaNode;

/**
 * AmICA Pet Movement in a real framework over real UDP: a pet collar's motion reports reach PetMovement
 * listeners, every one of them, and no person's movement device is made for the collar.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class AmicaPetMovementTest extends AmicaTestSupport {

    @Test
    public void aPetCollarBecomesAPetMovementSensor() throws Exception {
        try (AmicaNode node = node(2, 7, PET_COLLAR)) {
            node.keepAlive();
            device("AmicaPetMovement", node.id());
            PetMovementProvider pet = provider(PetMovementProvider.class, node.id());
            assertEquals(List.of("pet-collar"), providerNodeTypes(PetMovementProvider.class, node.id()));
            List<Boolean> heard = new CopyOnWriteArrayList<>();
            pet.connect((source, movement) -> heard.add(movement.detected()));

            node.send(new MotionDetection(true));
            node.send(new MotionDetection(true));
            node.send(new MotionDetection(false));
            awaitEquals("every report", List.of(true, true, false), () -> List.copyOf(heard));
            assertEquals(false, pet.lastMovement().orElseThrow().detected());
            assertEquals("a pet is not a person", Set.of(BUS, "AmicaPetMovement"), deviceTypesAt(node.id()));
        }
    }
}

package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.DIMMABLE_LIGHT;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;
import static org.tinysep.amica.protocol.AmicaNodeType.PET_COLLAR;
import static org.tinysep.amica.protocol.AmicaNodeType.SIMPLE_LIGHT;

import java.time.Instant;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.device.Device;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.itests.AmicaNode;

/**
 * Follow Me Light end to end in virtual time: real AmICA movement and light nodes over UDP, placed in the bedroom
 * and the hall. A walk from the bedroom to the hall puts exactly the expected Light Control commands on the light
 * nodes' sockets, in order: bedroom on, hall on (dimmable, configured brightness), bedroom off one grace period
 * after its last motion, then hall off.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class FollowMeLightTest extends AalTestSupport {

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.followmelight", Map.of("graceSeconds", "60", "brightness", "80"));
        return configs;
    }

    @Test
    public void theLightsFollowAWalkFromTheBedroomToTheHall() throws Exception {
        try (AalSync sync = sync();
                AmicaNode bedSensor = node(1, 41, MOVEMENT);
                AmicaNode hallSensor = node(1, 42, MOVEMENT);
                AmicaNode bedLight = node(1, 51, SIMPLE_LIGHT);
                AmicaNode hallLight = node(1, 52, DIMMABLE_LIGHT)) {
            Instant t = tomorrow();
            sync.tickDone(t);
            room("Bedroom", "Bedroom");
            room("Hall", "Hall");
            place(bedSensor, "AmicaMovement", "Bedroom");
            place(hallSensor, "AmicaMovement", "Hall");
            place(bedLight, "AmicaSimpleLight", "Bedroom");
            place(hallLight, "AmicaDimmableLight", "Hall");
            bedLight.send(new LightControl(0));
            hallLight.send(new LightControl(0));
            Device followMe = awaitService(Device.class, "(tinysep.driver.name=FollowMeLight)", TIMEOUT);
            await(TIMEOUT, () -> parameter(followMe, "lights").equals("2"), "both lights connected");
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);

            bedSensor.motion(true);
            expectCommand(bedLight, 5, 2, 0, 100);
            assertEquals(Occupancy.OCCUPIED, flat.occupancy());

            sync.tickDone(t.plusSeconds(30));
            hallSensor.motion(true);
            expectCommand(hallLight, 5, 2, 0, 80);

            sync.tickDone(t.plusSeconds(59));
            sync.tickDone(t.plusSeconds(60));
            expectCommand(bedLight, 5, 2, 0, 0);
            sync.tickDone(t.plusSeconds(89));
            sync.tickDone(t.plusSeconds(90));
            expectCommand(hallLight, 5, 2, 0, 0);
            assertEquals("", parameter(followMe, "litRooms"));
        }
    }

    @Test
    public void aPetMovesTheLightsOnlyWhileAPersonIsHome() throws Exception {
        try (AalSync sync = sync();
                AmicaNode collar = node(2, 7, PET_COLLAR);
                AmicaNode hallSensor = node(1, 42, MOVEMENT);
                AmicaNode bedLight = node(1, 51, SIMPLE_LIGHT);
                AmicaNode hallLight = node(1, 52, SIMPLE_LIGHT)) {
            Instant t = tomorrow();
            sync.tickDone(t);
            room("Bedroom", "Bedroom");
            room("Hall", "Hall");
            place(collar, "AmicaPetMovement", "Bedroom");
            place(hallSensor, "AmicaMovement", "Hall");
            place(bedLight, "AmicaSimpleLight", "Bedroom");
            place(hallLight, "AmicaSimpleLight", "Hall");
            Device followMe = awaitService(Device.class, "(tinysep.driver.name=FollowMeLight)", TIMEOUT);
            await(TIMEOUT, () -> parameter(followMe, "lights").equals("2"), "both lights connected");
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);

            collar.motion(true); // the pet alone: the flat is not occupied, nothing happens
            sync.tickDone(t.plusSeconds(10));
            hallSensor.motion(true); // a person: the same bus radio handles it after the pet's report
            expectCommand(hallLight, 5, 2, 0, 100);
            assertEquals(Occupancy.OCCUPIED, flat.occupancy());
            assertEquals("the pet's earlier motion lit nothing", "Hall", parameter(followMe, "litRooms"));

            collar.motion(true); // the pet with a person home: its room is lit too
            expectCommand(bedLight, 5, 2, 0, 100);
            assertEquals("Bedroom, Hall", parameter(followMe, "litRooms"));
        }
    }
}

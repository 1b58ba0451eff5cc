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
import org.tinysep.itests.SyncPeer;

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
        return replacing(super.initialConfigurations(), "org.tinysep.followmelight",
                Map.of("graceSeconds", "60", "brightness", "80"));
    }

    /**
     * The flat of both tests, in virtual time from {@link #t}: a Bedroom and a Hall, each with a sensor and a light
     * (the hall's movement sensor 1.42 and the bedroom's simple light 1.51; the bedroom sensor and the hall light
     * vary), all placed; {@link #followMe()} waits until Follow Me Light has both lights. Closes its nodes.
     */
    private final class BedroomAndHall implements AutoCloseable {
        final SyncPeer sync = sync();
        final AmicaNode bedSensor;
        final AmicaNode hallSensor = node(1, 42, MOVEMENT);
        final AmicaNode bedLight = node(1, 51, SIMPLE_LIGHT);
        final AmicaNode hallLight;
        final Instant t = tomorrow();

        BedroomAndHall(AmicaNode bedSensor, String bedSensorType, AmicaNode hallLight, String hallLightType)
                throws Exception {
            this.bedSensor = bedSensor;
            this.hallLight = hallLight;
            sync.tickDone(t);
            room("Bedroom", "Bedroom");
            room("Hall", "Hall");
            place(bedSensor, bedSensorType, "Bedroom");
            place(hallSensor, "AmicaMovement", "Hall");
            place(bedLight, "AmicaSimpleLight", "Bedroom");
            place(hallLight, hallLightType, "Hall");
        }

        /** @return Follow Me Light's device, once both lights are connected */
        Device followMe() {
            Device followMe = awaitService(Device.class, "(tinysep.driver.name=FollowMeLight)", TIMEOUT);
            await(TIMEOUT, () -> parameter(followMe, "lights").equals("2"), "both lights connected");
            return followMe;
        }

        @Override
        public void close() throws Exception {
            try (SyncPeer s = sync; AmicaNode a = bedSensor; AmicaNode b = hallSensor; AmicaNode c = bedLight;
                    AmicaNode d = hallLight) {
                // closes all, in reverse order, like the tests' try-with-resources did
            }
        }
    }

    @Test
    public void theLightsFollowAWalkFromTheBedroomToTheHall() throws Exception {
        try (BedroomAndHall home = new BedroomAndHall(node(1, 41, MOVEMENT), "AmicaMovement",
                node(1, 52, DIMMABLE_LIGHT), "AmicaDimmableLight")) {
            SyncPeer sync = home.sync;
            Instant t = home.t;
            home.bedLight.send(new LightControl(0));
            home.hallLight.send(new LightControl(0));
            Device followMe = home.followMe();
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);

            home.bedSensor.motion(true);
            expectCommand(home.bedLight, 5, 2, 0, 100);
            assertEquals(Occupancy.OCCUPIED, flat.occupancy());

            sync.tickDone(t.plusSeconds(30));
            home.hallSensor.motion(true);
            expectCommand(home.hallLight, 5, 2, 0, 80);

            sync.tickDone(t.plusSeconds(59));
            sync.tickDone(t.plusSeconds(60));
            expectCommand(home.bedLight, 5, 2, 0, 0);
            sync.tickDone(t.plusSeconds(89));
            sync.tickDone(t.plusSeconds(90));
            expectCommand(home.hallLight, 5, 2, 0, 0);
            assertEquals("", parameter(followMe, "litRooms"));
        }
    }

    @Test
    public void aPetMovesTheLightsOnlyWhileAPersonIsHome() throws Exception {
        try (BedroomAndHall home = new BedroomAndHall(node(2, 7, PET_COLLAR), "AmicaPetMovement",
                node(1, 52, SIMPLE_LIGHT), "AmicaSimpleLight")) {
            Device followMe = home.followMe();
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);

            home.bedSensor.motion(true); // the pet alone: the flat is not occupied, nothing happens
            home.sync.tickDone(home.t.plusSeconds(10));
            home.hallSensor.motion(true); // a person: the same bus radio handles it after the pet's report
            expectCommand(home.hallLight, 5, 2, 0, 100);
            assertEquals(Occupancy.OCCUPIED, flat.occupancy());
            assertEquals("the pet's earlier motion lit nothing", "Hall", parameter(followMe, "litRooms"));

            home.bedSensor.motion(true); // the pet with a person home: its room is lit too
            expectCommand(home.bedLight, 5, 2, 0, 100);
            assertEquals("Bedroom, Hall", parameter(followMe, "litRooms"));
        }
    }
}

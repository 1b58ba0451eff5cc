package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.DOOR;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;
import static org.tinysep.amica.protocol.AmicaNodeType.PET_COLLAR;
import static org.tinysep.amica.protocol.AmicaNodeType.SIMPLE_LIGHT;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;

/**
 * Two persons and a pet, in virtual time (Follow Me Light README: multi-person rule, pet rule). With two persons
 * moving in the living room and the kitchen, both rooms stay lit while each has motion within {@code graceSeconds}
 * (60 s), and each goes dark exactly 60 s after its own last motion. The pet's motion alone in an unoccupied flat
 * switches nothing (and does not make the flat occupied); with a person home, the pet's motion in the bedroom lights
 * the bedroom. Flat Occupancy's leave timeout is shortened to 120 s so the flat becomes UNOCCUPIED quickly.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class TwoPersonsAndPetTest extends VirtualFlatTestSupport {

    private static final String EVERYBODY_OUT = """
            09:00:00  door open           -- the last person leaves
            09:00:04  door closed         -- UNOCCUPIED at 09:02:04
            09:05:00  pet                 -- the cat, alone at home, in the bedroom
            09:05:30  pet
            09:06:00  pet
            """;

    private static final String TWO_PERSONS = """
            10:00:00  door open           -- both come home
            10:00:05  door closed
            10:00:08  motion Hall         -- within the exit grace: not evidence for Flat Occupancy, but the hall lights
            10:00:20  motion Living room  -- person A (cancels the leave check)
            10:00:30  motion Kitchen      -- person B
            10:01:10  motion Living room
            10:01:20  motion Kitchen
            10:02:00  motion Living room
            10:02:10  motion Kitchen
            10:02:50  motion Living room  -- A's last motion: the living room goes dark at 10:03:50
            10:03:00  motion Kitchen
            10:03:40  motion Kitchen
            10:04:30  motion Kitchen      -- B's last motion: the kitchen goes dark at 10:05:30
            10:06:00  motion Kitchen      -- B back in the kitchen
            10:06:10  pet                 -- the cat in the bedroom, with a person home
            """;

    private static final List<String> TWO_PERSONS_LIGHTS = List.of(
            "10:00:08 Hall light on",
            "10:00:20 Living room light on",
            "10:00:30 Kitchen light on",
            "10:01:08 Hall light off",
            "10:03:50 Living room light off",
            "10:05:30 Kitchen light off",
            "10:06:00 Kitchen light on",
            "10:06:10 Bedroom light on",
            "10:07:00 Kitchen light off",
            "10:07:10 Bedroom light off");

    private static final List<String> ROOMS = List.of("Hall", "Living room", "Kitchen", "Bedroom");

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.followmelight", Map.of("graceSeconds", "60", "brightness", "100"));
        configs.put("org.tinysep.flatoccupancy", Map.of("leaveTimeoutSeconds", "120", "exitGraceSeconds", "10"));
        return configs;
    }

    @Test
    public void eachRoomKeepsItsOwnGraceAndThePetMovesLightsOnlyWithAPersonHome() throws Exception {
        List<AutoCloseable> closing = new ArrayList<>();
        try (SyncPeer sync = sync()) {
            VirtualFlat flat = virtualFlat(sync, 200); // dense ticks cover the 120 s leave check and the 60 s grace
            closing.add(flat::close);
            ROOMS.forEach(r -> room(r, r));
            for (int i = 0; i < ROOMS.size(); i++) {
                closing.add(light(flat, node(1, 60 + i, SIMPLE_LIGHT), ROOMS.get(i)));
            }
            Map<String, AmicaNode> sensors = new LinkedHashMap<>();
            for (String room : List.of("Hall", "Living room", "Kitchen")) {
                AmicaNode n = node(1, 70 + sensors.size(), MOVEMENT);
                closing.add(n);
                motionSensor(flat, n, room);
                sensors.put(room, n);
            }
            AmicaNode door = node(1, 80, DOOR);
            closing.add(door);
            doorSensor(flat, door, "Hall");
            AmicaNode collar = node(2, 7, PET_COLLAR);
            closing.add(collar);
            petCollar(flat, collar, "Bedroom");
            FlatOccupancyProvider occupancy = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            flat.watch(occupancy);

            long wall = System.nanoTime();
            flat.play(FlatScript.parse(flat, EVERYBODY_OUT, sensors, door, collar), flat.at("09:10:00"));
            assertEquals("the pet does not make the flat occupied",
                    List.of("09:00:00 OCCUPIED", "09:02:04 UNOCCUPIED"), flat.occupancy);
            assertEquals("the pet alone switches nothing", List.of(), flat.commands);

            flat.play(FlatScript.parse(flat, TWO_PERSONS, sensors, door, collar), flat.at("10:10:00"));
            log.info("TwoPersonsAndPetTest: the script took {} ms wall time", (System.nanoTime() - wall) / 1_000_000);
            assertEquals("arrival; the leave check is cancelled by motion after the exit grace",
                    List.of("09:00:00 OCCUPIED", "09:02:04 UNOCCUPIED", "10:00:00 OCCUPIED"), flat.occupancy);
            assertEquals("Light Control commands received by the light nodes", TWO_PERSONS_LIGHTS, flat.commands);
            assertEquals("confirmations heard by the platform", TWO_PERSONS_LIGHTS, flat.confirmations);
        } finally {
            for (AutoCloseable c : closing) {
                c.close();
            }
        }
    }
}

package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.tinysep.amica.protocol.AmicaNodeType.DOOR;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;
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
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * A scripted day in one flat, in virtual time: arrival, moving through the rooms, leaving, returning, going to bed.
 * Real AmICA frames over UDP from movement sensors in five rooms and the hall's outer door; five simulated
 * simple-light nodes that confirm every command. Asserted exactly, with virtual times: Flat Occupancy's changes,
 * the Light Control commands each light node received (in order) and their confirmations, Inactivity
 * Recognition's states — and that no alert was raised and no mail reached the SMTP server.
 * <p>
 * Configuration (explicit, the documented defaults): Follow Me Light grace 60 s; Flat Occupancy leave timeout
 * 600 s, exit grace 10 s; Inactivity Recognition keeps its default limits (Hall 30, Bathroom 45, Kitchen 90,
 * Living room 180, Bedroom 600 min): the script's longest quiet spells while someone is home are 85 min after
 * kitchen activity (16:00 -> 17:25 is below 90), 135 min in the living room (19:00 -> 21:15, below 180) and the
 * night in the bedroom.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class ScriptedDayTest extends VirtualFlatTestSupport {

    /** The day: time, event, what the person does. */
    private static final String DAY = """
            07:00:00  motion Bedroom      -- gets up
            07:00:45  motion Bedroom
            07:01:15  motion Hall         -- to the bathroom
            07:01:30  motion Bathroom
            07:10:00  motion Bathroom     -- out of the shower
            07:10:30  motion Kitchen      -- breakfast
            07:30:00  motion Kitchen
            07:45:00  motion Living room  -- reads the paper
            08:29:40  motion Hall         -- puts the coat on
            08:30:00  door open           -- leaves
            08:30:04  door closed
            08:30:08  motion Hall         -- still seen by the hall sensor: within the exit grace
            12:00:00  door open           -- returns
            12:00:03  motion Hall
            12:00:06  door closed
            12:00:40  motion Kitchen      -- lunch: motion after the exit grace cancels the leave check
            13:30:00  motion Living room
            16:00:00  motion Kitchen
            17:25:00  motion Living room
            18:30:00  motion Kitchen      -- dinner
            19:00:00  motion Living room  -- television
            21:15:00  motion Living room
            22:20:00  motion Bathroom
            22:30:00  motion Bedroom      -- goes to bed
            """;

    private static final List<String> OCCUPANCY = List.of(
            "07:00:00 OCCUPIED",
            "08:40:04 UNOCCUPIED", // door closed at 08:30:04 + 600 s; the hall motion at 08:30:08 was the leaver
            "12:00:00 OCCUPIED"); // the door opened; the door closing at 12:00:06 starts no leave

    private static final List<String> INACTIVITY_STATES = List.of(
            "07:00:00 WATCHING",
            "08:40:04 NOT_WATCHING",
            "12:00:00 WATCHING");

    /** Every light goes off exactly 60 s after the last motion in its room. */
    private static final List<String> LIGHTS = List.of(
            "07:00:00 Bedroom light on",
            "07:01:15 Hall light on",
            "07:01:30 Bathroom light on",
            "07:01:45 Bedroom light off",
            "07:02:15 Hall light off",
            "07:02:30 Bathroom light off",
            "07:10:00 Bathroom light on",
            "07:10:30 Kitchen light on",
            "07:11:00 Bathroom light off",
            "07:11:30 Kitchen light off",
            "07:30:00 Kitchen light on",
            "07:31:00 Kitchen light off",
            "07:45:00 Living room light on",
            "07:46:00 Living room light off",
            "08:29:40 Hall light on",
            "08:31:08 Hall light off",
            "12:00:03 Hall light on", // not at 12:00:00: doors switch no lights
            "12:00:40 Kitchen light on",
            "12:01:03 Hall light off",
            "12:01:40 Kitchen light off",
            "13:30:00 Living room light on",
            "13:31:00 Living room light off",
            "16:00:00 Kitchen light on",
            "16:01:00 Kitchen light off",
            "17:25:00 Living room light on",
            "17:26:00 Living room light off",
            "18:30:00 Kitchen light on",
            "18:31:00 Kitchen light off",
            "19:00:00 Living room light on",
            "19:01:00 Living room light off",
            "21:15:00 Living room light on",
            "21:16:00 Living room light off",
            "22:20:00 Bathroom light on",
            "22:21:00 Bathroom light off",
            "22:30:00 Bedroom light on",
            "22:31:00 Bedroom light off");

    private static final List<String> ROOMS = List.of("Hall", "Living room", "Kitchen", "Bathroom", "Bedroom");

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.followmelight", Map.of("graceSeconds", "60", "brightness", "100"));
        configs.put("org.tinysep.flatoccupancy", Map.of("leaveTimeoutSeconds", "600", "exitGraceSeconds", "10"));
        configs.put("org.tinysep.inactivity", INACTIVITY_UTC);
        return configs;
    }

    @Test
    public void aNormalDayLightsTheRightRoomsAtTheRightTimesAndMailsNobody() throws Exception {
        List<AutoCloseable> closing = new ArrayList<>();
        try (SmtpSink sink = new SmtpSink().start(); SyncPeer sync = sync()) {
            MailManagerProvider mail = mailTo(sink, "carer@care.test");

            VirtualFlat flat = virtualFlat(sync, 700); // dense ticks cover the 600 s leave check and the 60 s grace
            closing.add(flat::close);
            ROOMS.forEach(r -> room(r, r));
            for (int i = 0; i < ROOMS.size(); i++) {
                AmicaNode n = node(1, 60 + i, SIMPLE_LIGHT);
                closing.add(light(flat, n, ROOMS.get(i)));
            }
            Map<String, AmicaNode> sensors = new LinkedHashMap<>();
            for (int i = 0; i < ROOMS.size(); i++) {
                AmicaNode n = node(1, 70 + i, MOVEMENT);
                closing.add(n);
                motionSensor(flat, n, ROOMS.get(i));
                sensors.put(ROOMS.get(i), n);
            }
            AmicaNode door = node(1, 80, DOOR);
            closing.add(door);
            doorSensor(flat, door, "Hall");
            flat.watch(awaitService(FlatOccupancyProvider.class, null, TIMEOUT));
            InactivityRecognitionProvider inactivity = awaitService(InactivityRecognitionProvider.class, null,
                    TIMEOUT);
            flat.watch(inactivity);

            long wall = System.nanoTime();
            flat.play(FlatScript.parse(flat, DAY, sensors, door, null), flat.at("22:45:00"));
            log.info("ScriptedDayTest: the virtual day took {} ms wall time", (System.nanoTime() - wall) / 1_000_000);

            assertEquals("Flat Occupancy's changes", OCCUPANCY, flat.occupancy);
            assertEquals("Light Control commands received by the light nodes", LIGHTS, flat.commands);
            assertEquals("confirmations heard by the platform", LIGHTS, flat.confirmations);
            assertEquals("Inactivity Recognition's states (never ALERT)", INACTIVITY_STATES, flat.inactivity);
            assertEquals(InactivityState.WATCHING, inactivity.state());
            assertEquals("no mail on a normal day", List.of(), sink.messages());
            assertEquals(MailStatus.IDLE, mail.status());
        } finally {
            for (AutoCloseable c : closing) {
                c.close();
            }
        }
    }
}

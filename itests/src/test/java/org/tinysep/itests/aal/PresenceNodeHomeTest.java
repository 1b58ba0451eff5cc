package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.DOOR;
import static org.tinysep.amica.protocol.AmicaNodeType.PRESENCE_BED;
import static org.tinysep.amica.protocol.AmicaNodeType.PRESENCE_SEAT;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.itests.AmicaNode;

/**
 * AmICA presence nodes end to end (issue 11): a node announcing a presence type (product-id bits 8..11) becomes an
 * AmICA Presence device providing {@code PresenceProvider}, and Flat Occupancy and Inactivity Recognition, which
 * consume that interface, take a mat for a person. A seat mat that is ON keeps the flat OCCUPIED after the outer
 * door closed with nothing else happening (a visitor left; replayed as a window, the flat went empty after the
 * leave check), and a bed mat ON puts the detector in the sleep state.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class PresenceNodeHomeTest extends AalTestSupport {

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.inactivity", Map.of("timeZone", "UTC"));
        return configs;
    }

    @Test
    public void aSeatMatThatIsOnKeepsTheFlatOccupiedAfterTheOuterDoorClosed() throws Exception {
        try (AalSync sync = sync(); AmicaNode front = node(1, 71, DOOR); AmicaNode seat = node(1, 72, PRESENCE_SEAT)) {
            Instant t = tomorrow();
            sync.tickDone(t);
            room("Hall", "Hall");
            room("Living Room", "Living room");
            place(front, "AmicaDoor", "Hall");
            Device mat = place(seat, "AmicaPresence", "Living Room");
            shell("tinysep:set " + mat.uid() + " name \"Seat (Pressure)\"");
            PresenceProvider presence = awaitService(PresenceProvider.class,
                    "(" + DeviceProperties.NODE_ADDRESS + "=" + seat.id() + ")", TIMEOUT);
            assertEquals(PresenceKind.SEAT, presence.kind());
            ServiceReference<?> ref = context.getServiceReferences(PresenceProvider.class.getName(),
                    "(" + DeviceProperties.NODE_ADDRESS + "=" + seat.id() + ")")[0];
            assertEquals(List.of("presence-seat"), List.of((String[]) ref.getProperty(DeviceProperties.NODE_TYPE)));
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            InactivityRecognitionProvider inactivity = awaitService(InactivityRecognitionProvider.class, null,
                    TIMEOUT);
            Device detector = awaitService(Device.class, "(tinysep.device.uid=" + inactivity.deviceUid() + ")",
                    TIMEOUT);
            Device flatDevice = awaitService(Device.class, "(tinysep.device.uid=" + flat.deviceUid() + ")", TIMEOUT);
            front.door(false); // first reports: resting states, no activity
            seat.door(false);
            await(TIMEOUT, () -> flatDevice.connections().size() >= 2, "Flat Occupancy connected to door and mat");
            await(TIMEOUT, () -> "OFF".equals(parameter(mat, "state")), "the mat's first report");

            // she comes home and sits down; later a visitor leaves: the front door opens and closes, then nothing
            front.door(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "OCCUPIED on arrival");
            sync.tickDone(t.plusSeconds(5));
            front.door(false);
            sync.tickDone(t.plusSeconds(60));
            seat.door(true); // Reed-Switch Status A = 1: the seat mat is ON
            await(TIMEOUT, () -> presence.present(), "the seat mat ON");
            await(TIMEOUT, () -> parameter(detector, "lastActivity").contains("seat Seat (Pressure) on"),
                    "the mat turning on is activity in the Living Room: " + parameter(detector, "lastActivity"));
            await(TIMEOUT, () -> parameter(flatDevice, "someoneHere").contains(mat.uid()),
                    "Flat Occupancy lists the mat as someone here");

            Instant visitorLeaves = t.plus(Duration.ofMinutes(30));
            sync.tickDone(visitorLeaves);
            front.door(true);
            sync.tickDone(visitorLeaves.plusSeconds(5));
            front.door(false);
            await(TIMEOUT, () -> !parameter(flatDevice, "leaveCheckUntil").isEmpty(), "the leave check started");
            sync.tickDone(visitorLeaves.plusSeconds(5 + 600 + 60));
            await(TIMEOUT, () -> parameter(flatDevice, "leaveCheckUntil").isEmpty(), "the leave check ended");
            assertEquals("the seat mat ON says someone is here: no motion needed", Occupancy.OCCUPIED,
                    flat.occupancy());
            assertEquals(InactivityState.WATCHING, inactivity.state());

            // she sits on and on, nothing else happens: the living room's limit runs from the last activity
            // (the front door closing); the alert names the mat's room and what the detector knows
            Instant deadline = Instant.parse(parameter(detector, "deadline"));
            sync.tickDone(deadline);
            await(TIMEOUT, () -> inactivity.state() == InactivityState.ALERT, "the alert at " + deadline);
            InactivityAlert alert = inactivity.alert().orElseThrow();
            assertTrue(alert.lastActivity(), alert.lastActivity().startsWith("door "));
            assertEquals("Occupancy never went away while she sat", Occupancy.OCCUPIED, flat.occupancy());
        }
    }

    @Test
    public void aBedMatTurningOnPutsTheDetectorInTheSleepState() throws Exception {
        try (AalSync sync = sync(); AmicaNode front = node(1, 73, DOOR); AmicaNode bed = node(1, 74, PRESENCE_BED)) {
            Instant t = tomorrow();
            sync.tickDone(t);
            room("Hall", "Hall");
            room("Bedroom", "Bedroom");
            place(front, "AmicaDoor", "Hall");
            Device mat = place(bed, "AmicaPresence", "Bedroom");
            assertEquals("BED", parameter(mat, "kind"));
            InactivityRecognitionProvider inactivity = awaitService(InactivityRecognitionProvider.class, null,
                    TIMEOUT);
            Device detector = awaitService(Device.class, "(tinysep.device.uid=" + inactivity.deviceUid() + ")",
                    TIMEOUT);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            front.door(false);
            bed.door(false);
            await(TIMEOUT, () -> "OFF".equals(parameter(mat, "state")), "the mat's first report");
            front.door(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "OCCUPIED on arrival");
            sync.tickDone(t.plusSeconds(5));
            front.door(false);
            sync.tickDone(t.plusSeconds(30));
            bed.door(true); // she lies down (by day: only the mat says she is in bed)
            await(TIMEOUT, () -> parameter(detector, "lastActivity").contains("bed Bed mat " + bed.id() + " on"),
                    "the bed mat is activity: " + parameter(detector, "lastActivity"));
            String reason = parameter(detector, "limitReason");
            assertTrue("the bed mat gives the sleep state: " + reason, reason.contains("asleep"));
            assertEquals(InactivityState.WATCHING, inactivity.state());
        }
    }
}

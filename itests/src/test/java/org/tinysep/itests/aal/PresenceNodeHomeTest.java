package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.DOOR;
import static org.tinysep.amica.protocol.AmicaNodeType.PRESENCE_BED;
import static org.tinysep.amica.protocol.AmicaNodeType.PRESENCE_SEAT;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.temporal.ChronoUnit;
import java.util.List;
import java.util.Locale;
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
import org.tinysep.itests.SyncPeer;

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

    /** A hall with the front door and one room with a mat, both nodes' first reports in, OCCUPIED on arrival. */
    private record Home(Instant start, Device mat, PresenceProvider presence, FlatOccupancyProvider flat,
                        Device flatDevice, InactivityRecognitionProvider inactivity, Device detector) {
    }

    private Home arrive(SyncPeer sync, Instant t, AmicaNode front, AmicaNode matNode, String room, String type)
            throws Exception {
        sync.tickDone(t);
        room("Hall", "Hall");
        room(room, type);
        place(front, "AmicaDoor", "Hall");
        Device mat = place(matNode, "AmicaPresence", room);
        String byNode = "(" + DeviceProperties.NODE_ADDRESS + "=" + matNode.id() + ")";
        PresenceProvider presence = awaitService(PresenceProvider.class, byNode, TIMEOUT);
        ServiceReference<?> ref = context.getServiceReferences(PresenceProvider.class.getName(), byNode)[0];
        assertEquals(List.of("presence-" + presence.kind().name().toLowerCase(Locale.ROOT)),
                List.of((String[]) ref.getProperty(DeviceProperties.NODE_TYPE)));
        FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
        InactivityRecognitionProvider inactivity = awaitService(InactivityRecognitionProvider.class, null, TIMEOUT);
        Device detector = awaitService(Device.class, "(tinysep.device.uid=" + inactivity.deviceUid() + ")", TIMEOUT);
        Device flatDevice = awaitService(Device.class, "(tinysep.device.uid=" + flat.deviceUid() + ")", TIMEOUT);
        front.door(false); // first reports: resting states, no activity
        matNode.door(false);
        await(TIMEOUT, () -> flatDevice.connections().size() >= 2, "Flat Occupancy connected to door and mat");
        await(TIMEOUT, () -> "OFF".equals(parameter(mat, "state")), "the mat's first report");
        front.door(true);
        await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "OCCUPIED on arrival");
        sync.tickDone(t.plusSeconds(5));
        front.door(false);
        return new Home(t, mat, presence, flat, flatDevice, inactivity, detector);
    }

    @Test
    public void aSeatMatThatIsOnKeepsTheFlatOccupiedAfterTheOuterDoorClosed() throws Exception {
        try (SyncPeer sync = sync(); AmicaNode front = node(1, 71, DOOR); AmicaNode seat = node(1, 72, PRESENCE_SEAT)) {
            Home h = arrive(sync, tomorrow(), front, seat, "Living Room", "Living room");
            assertEquals(PresenceKind.SEAT, h.presence().kind());
            shell("tinysep:set " + h.mat().uid() + " name \"Seat (Pressure)\"");
            sync.tickDone(h.start().plusSeconds(60));
            seat.door(true); // Reed-Switch Status A = 1: she sits down, the seat mat is ON
            await(TIMEOUT, () -> h.presence().present(), "the seat mat ON");
            await(TIMEOUT, () -> parameter(h.detector(), "lastActivity").contains("seat Seat (Pressure) on"),
                    "the mat turning on is activity in the Living Room");
            await(TIMEOUT, () -> parameter(h.flatDevice(), "someoneHere").contains(h.mat().uid()),
                    "Flat Occupancy lists the mat as someone here");

            // a visitor leaves: the front door opens and closes, then nothing (no motion sensor in this home)
            Instant visitorLeaves = h.start().plus(Duration.ofMinutes(30));
            sync.tickDone(visitorLeaves);
            front.door(true);
            sync.tickDone(visitorLeaves.plusSeconds(5));
            front.door(false);
            await(TIMEOUT, () -> !parameter(h.flatDevice(), "leaveCheckUntil").isEmpty(), "the leave check started");
            sync.tickDone(visitorLeaves.plusSeconds(5 + 600 + 60));
            await(TIMEOUT, () -> parameter(h.flatDevice(), "leaveCheckUntil").isEmpty(), "the leave check ended");
            assertEquals("the seat mat ON says someone is here: no motion needed", Occupancy.OCCUPIED,
                    h.flat().occupancy());
            assertEquals(InactivityState.WATCHING, h.inactivity().state());

            // nothing more happens: the alert is raised while the flat is still occupied. Today's detector counts
            // the quiet time from the last activity and names its room (the door in the Hall), not the mat that
            // is still ON (Inactivity Recognition's logic, unchanged here)
            Instant deadline = Instant.parse(parameter(h.detector(), "deadline"));
            sync.tickDone(deadline);
            await(TIMEOUT, () -> h.inactivity().state() == InactivityState.ALERT, "the alert at " + deadline);
            InactivityAlert alert = h.inactivity().alert().orElseThrow();
            assertTrue(alert.lastActivity(), alert.lastActivity().startsWith("door "));
            assertEquals("Hall", alert.roomName());
            assertEquals(Occupancy.OCCUPIED, h.flat().occupancy());
        }
    }

    @Test
    public void aBedMatTurningOnPutsTheDetectorInTheSleepState() throws Exception {
        try (SyncPeer sync = sync(); AmicaNode front = node(1, 73, DOOR); AmicaNode bed = node(1, 74, PRESENCE_BED)) {
            // by day (noon in the platform's zone): only the mat can say that she is in bed, not the night
            Instant noon = tomorrow().atZone(ZoneId.systemDefault()).truncatedTo(ChronoUnit.DAYS).plusDays(1)
                    .plusHours(12).toInstant();
            Home h = arrive(sync, noon, front, bed, "Bedroom", "Bedroom");
            assertEquals("BED", parameter(h.mat(), "kind"));
            sync.tickDone(h.start().plusSeconds(30));
            bed.door(true); // she lies down
            await(TIMEOUT, () -> parameter(h.detector(), "lastActivity").contains("bed Bed mat " + bed.id() + " on"),
                    "the bed mat is activity in the Bedroom");
            String reason = parameter(h.detector(), "limitReason");
            assertTrue("the bed mat gives the sleep state: " + reason, reason.contains("asleep"));
            assertEquals(InactivityState.WATCHING, h.inactivity().state());
        }
    }
}

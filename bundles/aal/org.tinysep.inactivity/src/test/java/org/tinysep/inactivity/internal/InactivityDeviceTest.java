package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.time.PlatformClock;

/** The device wired to fakes of its providers: rooms from the directory, one mail per alert. */
class InactivityDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T09:00:00Z");
    private Instant now = T0;
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final Fakes.Directory directory = new Fakes.Directory();
    private final InactivityDevice device = new InactivityDevice(
            new DriverContext(null, "d", "InactivityRecognition", logs.reporter(), new PlatformClock(() -> now)),
            directory, LimitTable.parse(120, "Bathroom=45, Hall=30", ""), new AlertMail(ZoneOffset.UTC));
    private final Fakes.Movement bathSensor = new Fakes.Movement("m-bath");
    private final Fakes.Door bathDoor = new Fakes.Door("d-bath");
    private final Fakes.Flat flat = new Fakes.Flat("flat", Occupancy.OCCUPIED, T0);
    private final Fakes.Mail mail = new Fakes.Mail("mail");
    private final List<String> states = new ArrayList<>();

    InactivityDeviceTest() {
        directory.rooms.put("m-bath", "r-bath");
        directory.rooms.put("d-bath", "r-bath");
        directory.names.put("m-bath", "Bath sensor");
        directory.names.put("d-bath", "Bath door");
        device.use(house(new Room("r-bath", "Bathroom", "Bathroom", Set.of()),
                new Room("r-hall", "Hall", "Hall", Set.of())));
        device.watch(bathSensor);
        device.watch(bathDoor);
        device.connect((src, s, at) -> states.add(s + "@" + at));
    }

    private void tickUntil(Instant until) {
        while (now.isBefore(until)) {
            now = now.plusSeconds(1);
            device.tick(now);
        }
    }

    @Test
    void aContactsFirstReportIsNoActivityItsChangesAre() {
        device.use(flat);
        tickUntil(T0.plusSeconds(600));
        bathSensor.report(true, T0.plusSeconds(600));
        tickUntil(T0.plusSeconds(600 + 45 * 60 + 60));
        assertEquals(InactivityState.ALERT, device.state());

        bathDoor.change(OpenState.CLOSED, now); // power-up or platform restart: the node tells its state
        assertEquals(InactivityState.ALERT, device.state(), "a first report does not answer the alert");
        bathDoor.change(OpenState.CLOSED, now); // a repeat
        assertEquals(InactivityState.ALERT, device.state());
        bathDoor.change(OpenState.OPEN, now); // someone opened it
        assertEquals(InactivityState.WATCHING, device.state());
    }

    @Test
    void aContactConnectedWithAKnownStateCountsItsNextChange() {
        Fakes.Door hallDoor = new Fakes.Door("d-hall");
        directory.rooms.put("d-hall", "r-bath");
        hallDoor.change(OpenState.CLOSED, T0); // reported before this device connected (e.g. it was updated)
        device.use(flat);
        device.watch(hallDoor);
        bathSensor.report(true, T0.plusSeconds(600));
        tickUntil(T0.plusSeconds(600 + 45 * 60 + 60));
        assertEquals(InactivityState.ALERT, device.state());
        hallDoor.change(OpenState.OPEN, now);
        assertEquals(InactivityState.WATCHING, device.state(), "a change from the state known at connection");
    }

    @Test
    void oneMailPerAlertNamingRoomActivityAndTime() {
        device.use(mail);
        device.use(flat);
        bathDoor.change(OpenState.CLOSED, T0); // the door's first report: its state, no activity
        tickUntil(T0.plusSeconds(600)); // reports are stamped with the platform's time: never ahead of it
        bathSensor.report(true, T0.plusSeconds(600));
        tickUntil(T0.plusSeconds(600 + 45 * 60 + 300));
        assertEquals(InactivityState.ALERT, device.state());
        assertEquals(1, mail.sent.size(), "repeated ticks do not resend");
        String m = mail.sent.get(0);
        assertTrue(m.startsWith("TinySEP: no activity in Bathroom since 09:10\n"), m);
        assertTrue(m.contains("Last activity: movement by Bath sensor"), m);
        assertEquals("Bathroom", device.alert().orElseThrow().roomName());

        bathDoor.change(OpenState.OPEN, now);
        assertEquals(InactivityState.WATCHING, device.state());
        assertEquals(Optional.empty(), device.alert());
        assertEquals(List.of("WATCHING@" + T0, "ALERT@" + T0.plusSeconds(600 + 45 * 60), "WATCHING@" + now), states);
        assertTrue(logs.events().stream().anyMatch(e -> e.message().startsWith("inactivity alert")));
    }

    @Test
    void aDeviceWithoutRoomUsesTheDefaultLimitAndSaysSo() {
        device.use(mail);
        device.use(flat);
        directory.rooms.remove("m-bath");
        bathSensor.report(true, T0);
        tickUntil(T0.plusSeconds(119 * 60));
        assertEquals(InactivityState.WATCHING, device.state());
        tickUntil(T0.plusSeconds(120 * 60));
        assertEquals("unknown room (device Bath sensor)", device.alert().orElseThrow().roomName());
        assertEquals(1, mail.sent.size());
    }

    @Test
    void theRoomIsReadWhenTheActivityArrives() {
        device.use(flat);
        directory.rooms.put("m-bath", "r-hall"); // the user moved the sensor to the hall
        bathSensor.report(true, T0);
        tickUntil(T0.plusSeconds(30 * 60));
        assertEquals("Hall", device.alert().orElseThrow().roomName());
    }

    @Test
    void outdoorAndNoMotionReportsAreNoActivity() {
        device.use(flat);
        bathSensor.report(true, T0);
        bathSensor.report(false, T0.plusSeconds(600));
        bathSensor.location = MovementLocation.OUTSIDE;
        bathSensor.report(true, T0.plusSeconds(900));
        tickUntil(T0.plusSeconds(45 * 60));
        assertEquals(InactivityState.ALERT, device.state());
        assertEquals(T0, device.alert().orElseThrow().lastActivityAt());
    }

    @Test
    void anAlertWithoutMailManagerIsMailedWhenOneAppears() {
        device.use(flat);
        bathSensor.report(true, T0);
        tickUntil(T0.plusSeconds(45 * 60));
        assertEquals(DeviceStatus.State.ERROR, device.status().state());
        device.use(mail);
        device.use(mail);
        assertEquals(1, mail.sent.size());
        assertEquals(DeviceStatus.State.ONLINE, device.status().state());
    }

    @Test
    void onlyWatchesAnOccupiedFlat() {
        flat.occupancy = Occupancy.UNOCCUPIED;
        device.use(mail);
        device.use(flat);
        bathSensor.report(true, T0);
        tickUntil(T0.plusSeconds(3600));
        assertEquals(InactivityState.NOT_WATCHING, device.state());
        flat.change(Occupancy.OCCUPIED, now);
        assertEquals(InactivityState.WATCHING, device.state());
        device.forget("flat");
        assertEquals(InactivityState.NOT_WATCHING, device.state(), "without Flat Occupancy nobody is known home");
        tickUntil(T0.plusSeconds(4 * 3600));
        assertEquals(0, mail.sent.size());
    }

    static HouseInformationProvider house(Room... rooms) {
        return new FakeHouse(rooms);
    }

    /** Issue 25, item 1: Inactivity Recognition watches the person: it says which rooms it can no longer see. */
    @Test
    void itWatchesThePersonAndListsTheRoomsItCannotSee() {
        assertEquals("", device.parameters().stream().filter(p -> p.key().equals("roomsNotSeen")).findFirst()
                .orElseThrow(() -> new AssertionError("no roomsNotSeen parameter")).value());
    }
}

package org.tinysep.followmelight.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.Percent;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/** The device wired to fakes: lights found by their room at switching time, only its own lights switched off. */
class FollowMeDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T19:00:00Z");
    private Instant now = T0;
    private final List<String> journal = new ArrayList<>();
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final Fakes.Directory directory = new Fakes.Directory();
    private final FollowMeDevice device = new FollowMeDevice(
            new DriverContext(null, "d", "FollowMeLight", logs.reporter(), new PlatformClock(() -> now)),
            directory, Duration.ofSeconds(30), Percent.of(70));
    private final Fakes.Simple bedLamp = new Fakes.Simple("bed-lamp", journal);
    private final Fakes.Simple hallLamp = new Fakes.Simple("hall-lamp", journal);
    private final Fakes.Dimmable kitchenSpot = new Fakes.Dimmable("kitchen-spot", journal);
    private final Fakes.Movement bedSensor = new Fakes.Movement("bed-sensor");
    private final Fakes.Movement hallSensor = new Fakes.Movement("hall-sensor");
    private final Fakes.Movement kitchenSensor = new Fakes.Movement("kitchen-sensor");
    private final Fakes.Flat flat = new Fakes.Flat("flat", Occupancy.OCCUPIED, T0);

    FollowMeDeviceTest() {
        place("bedroom", "bed-lamp", "bed-sensor");
        place("hall", "hall-lamp", "hall-sensor");
        place("kitchen", "kitchen-spot", "kitchen-sensor");
        device.control(bedLamp);
        device.control(hallLamp);
        device.control(kitchenSpot);
        device.use(bedSensor);
        device.use(hallSensor);
        device.use(kitchenSensor);
    }

    private void place(String room, String... uids) {
        for (String uid : uids) {
            directory.rooms.put(uid, room);
        }
    }

    private void advance(int seconds) {
        for (int i = 0; i < seconds; i++) {
            now = now.plusSeconds(1);
            device.tick(now);
        }
    }

    @Test
    void lightsFollowTheWalkAndDimmableLightsGetTheConfiguredBrightness() {
        device.use(flat);
        bedSensor.report(now);
        bedSensor.report(now);
        advance(10);
        hallSensor.report(now);
        advance(10);
        kitchenSensor.report(now);
        advance(60);
        assertEquals(List.of("bed-lamp on", "hall-lamp on", "kitchen-spot 70%", "bed-lamp off", "hall-lamp off",
                "kitchen-spot 0%"), journal);
        assertTrue(logs.events().stream().anyMatch(e -> e.message().equals("room hall lit (motion): on hall-lamp")));
    }

    @Test
    void aLightSwitchedOnByHandIsNeverSwitchedOff() {
        device.use(flat);
        hallLamp.confirm(true, now); // someone switched it on by hand
        hallSensor.report(now);
        advance(40);
        flat.change(Occupancy.UNOCCUPIED, now);
        assertEquals(List.of(), journal);
    }

    @Test
    void leavingSwitchesOffWhatThisServiceSwitchedOnEvenAfterTheLampMoved() {
        device.use(flat);
        bedSensor.report(now);
        place("hall", "bed-lamp"); // the user moved the lamp
        flat.change(Occupancy.UNOCCUPIED, now.plusSeconds(5));
        assertEquals(List.of("bed-lamp on", "bed-lamp off"), journal);
        bedSensor.report(now.plusSeconds(6));
        advance(60);
        assertEquals(2, journal.size(), "nothing happens while the flat is unoccupied");
    }

    @Test
    void petMovesLightsOnlyWithSomeoneHome() {
        Fakes.Pet collar = new Fakes.Pet("collar");
        place("kitchen", "collar");
        device.use(collar);
        flat.occupancy = Occupancy.UNOCCUPIED;
        device.use(flat);
        collar.report(now);
        assertEquals(List.of(), journal);
        flat.change(Occupancy.OCCUPIED, now.plusSeconds(10));
        collar.report(now.plusSeconds(11));
        assertEquals(List.of("kitchen-spot 70%"), journal);
    }

    @Test
    void aLightSwitchedOffByHandIsForgotten() {
        device.use(flat);
        bedSensor.report(now);
        bedLamp.confirm(true, now);
        bedLamp.confirm(false, now.plusSeconds(2));
        advance(40);
        assertEquals(List.of("bed-lamp on"), journal);
    }

    @Test
    void anUnplacedSensorIsReportedOnceAndIgnored() {
        device.use(flat);
        Fakes.Movement stray = new Fakes.Movement("stray");
        device.use(stray);
        stray.report(now);
        stray.report(now);
        assertEquals(List.of(), journal);
        assertEquals(1, logs.events().stream().filter(e -> e.message().contains("not placed in a room")).count());
    }
}

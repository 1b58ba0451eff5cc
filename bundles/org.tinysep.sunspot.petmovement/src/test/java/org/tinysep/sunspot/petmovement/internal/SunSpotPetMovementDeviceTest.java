package org.tinysep.sunspot.petmovement.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.PlatformClock;
import org.tinysep.device.support.RecordingLogs;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/** Pet Movement Detection payloads in, pet movement reports out. */
class SunSpotPetMovementDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    private static final int PET = SunSpotSensorType.PET_COLLAR.code();

    private final FakeSunSpotBus bus = new FakeSunSpotBus();
    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final SunSpotPetMovementDevice collar = new SunSpotPetMovementDevice(
            new DriverContext(null, "d", "SunSpotPetMovement", logs.reporter(), new PlatformClock(() -> T0)), bus);
    private final List<MovementEvent> heard = new ArrayList<>();

    SunSpotPetMovementDeviceTest() {
        collar.connect((src, e) -> heard.add(e));
    }

    private void feed(boolean moved, int second) {
        collar.payloadReceived(bus, PET, SunSpotPayloads.encode(new PetMovementDetection(moved)),
                T0.plusSeconds(second));
    }

    @Test
    void everyReportIsPassedOnAndTheEventLogGetsChanges() {
        feed(true, 0);
        feed(true, 2);
        feed(false, 4);
        feed(false, 6);
        feed(true, 8);

        assertEquals(List.of(new MovementEvent(true, T0), new MovementEvent(true, T0.plusSeconds(2)),
                new MovementEvent(false, T0.plusSeconds(4)), new MovementEvent(false, T0.plusSeconds(6)),
                new MovementEvent(true, T0.plusSeconds(8))), heard);
        assertEquals(new MovementEvent(true, T0.plusSeconds(8)), collar.lastMovement().orElseThrow());
        List<String> logged = logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT)
                .map(EventEntry::message).toList();
        assertEquals(List.of("pet movement detected", "no pet movement", "pet movement detected"), logged);
    }

    @Test
    void aPersonsMovementOnTheSameNodeIsNotAPetsAndBadPayloadsGiveNoEventAndNoException() {
        collar.payloadReceived(bus, SunSpotSensorType.MOVEMENT.code(),
                SunSpotPayloads.encode(new MovementDetection(true)), T0);
        assertEquals(DeviceStatus.State.UNKNOWN, collar.status().state(), "nothing of ours arrived yet");

        collar.payloadReceived(bus, PET, new byte[] {5, 1, 0, 2}, T0); // neither 0 nor 1
        collar.payloadReceived(bus, PET, new byte[] {5, 1, 7, 1}, T0); // reserved byte set
        collar.payloadReceived(bus, PET, new byte[] {5}, T0);
        collar.payloadReceived(bus, PET, SunSpotPayloads.encode(new MovementDetection(true)), T0);

        assertEquals(List.of(), heard);
        assertTrue(collar.lastMovement().isEmpty());
        assertEquals("4", collar.parameters().stream().filter(p -> p.key().equals("rejectedPayloads"))
                .map(Parameter::value).findFirst().orElseThrow());
        assertEquals(DeviceStatus.State.ERROR, collar.status().state());

        feed(true, 1);
        assertEquals(List.of(new MovementEvent(true, T0.plusSeconds(1))), heard);
        assertEquals(DeviceStatus.State.ONLINE, collar.status().state());
    }
}

package org.tinysep.sunspot.petmovement.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.device.support.testing.SunSpotDeviceTestSupport;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/** Pet Movement Detection payloads in, pet movement reports out. */
class SunSpotPetMovementDeviceTest extends SunSpotDeviceTestSupport<SunSpotPetMovementDevice, Boolean> {

    SunSpotPetMovementDeviceTest() {
        super("SunSpotPetMovement", SunSpotSensorType.PET_COLLAR.code(), SunSpotPetMovementDevice::new,
                moved -> SunSpotPayloads.encode(new PetMovementDetection(moved)));
        sensor.connect((src, e) -> heard.add(e));
    }

    @Test
    void everyReportIsPassedOnAndTheEventLogGetsChanges() {
        feedEvery(2, true, true, false, false, true);

        assertEquals(List.of(new MovementEvent(true, T0), new MovementEvent(true, T0.plusSeconds(2)),
                new MovementEvent(false, T0.plusSeconds(4)), new MovementEvent(false, T0.plusSeconds(6)),
                new MovementEvent(true, T0.plusSeconds(8))), heard);
        assertEquals(new MovementEvent(true, T0.plusSeconds(8)), sensor.lastMovement().orElseThrow());
        List<String> logged = logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT)
                .map(EventEntry::message).toList();
        assertEquals(List.of("pet movement detected", "no pet movement", "pet movement detected"), logged);
    }

    @Test
    void aPersonsMovementOnTheSameNodeIsNotAPetsAndBadPayloadsGiveNoEventAndNoException() {
        sensor.payloadReceived(bus, SunSpotSensorType.MOVEMENT.code(),
                SunSpotPayloads.encode(new MovementDetection(true)), T0);
        assertEquals(DeviceStatus.State.UNKNOWN, sensor.status().state(), "nothing of ours arrived yet");

        deliver(new byte[] {5, 1, 0, 2}, 0); // neither 0 nor 1
        deliver(new byte[] {5, 1, 7, 1}, 0); // reserved byte set
        deliver(new byte[] {5}, 0);
        deliver(SunSpotPayloads.encode(new MovementDetection(true)), 0);

        assertEquals(List.of(), heard);
        assertTrue(sensor.lastMovement().isEmpty());
        assertEquals("4", sensor.parameters().stream().filter(p -> p.key().equals("rejectedPayloads"))
                .map(Parameter::value).findFirst().orElseThrow());
        assertEquals(DeviceStatus.State.ERROR, sensor.status().state());

        feed(true, 1);
        assertEquals(List.of(new MovementEvent(true, T0.plusSeconds(1))), heard);
        assertEquals(DeviceStatus.State.ONLINE, sensor.status().state());
    }
}

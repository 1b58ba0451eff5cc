package org.tinysep.amica.petmovement.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.tinysep.device.support.testing.TestPlatform.T0;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.device.support.testing.TestPlatform;

/** Motion Detection payloads of a pet collar in, pet movement reports out. */
class AmicaPetMovementDeviceTest {

    private final FakeBus bus = new FakeBus("2.7", "pet-collar", "window");
    private final TestPlatform platform = new TestPlatform();
    private final AmicaPetMovementDevice pet = new AmicaPetMovementDevice(
            platform.context(AmicaPetMovementDriver.NAME), bus);

    @Test
    void everyReportIsPassedOnTheEventLogGetsChangesAndOtherPayloadsAreIgnored() {
        List<MovementEvent> seen = new ArrayList<>();
        pet.connect((source, movement) -> seen.add(movement));
        assertEquals(Optional.empty(), pet.lastMovement());

        pet.payloadReceived(bus, AmicaPayloads.encode(new MotionDetection(true)), T0);
        pet.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(true)), T0.plusSeconds(1));
        pet.payloadReceived(bus, AmicaPayloads.encode(new LightControl(1)), T0.plusSeconds(1));
        pet.payloadReceived(bus, AmicaPayloads.encode(new KeepAlive(1, 2500, 1, 0x44, 3)), T0.plusSeconds(1));
        pet.payloadReceived(bus, new byte[] {100, 5, 0, 7}, T0.plusSeconds(1)); // rejected by the bus radio anyway
        pet.payloadReceived(bus, AmicaPayloads.encode(new MotionDetection(true)), T0.plusSeconds(2));
        pet.payloadReceived(bus, AmicaPayloads.encode(new MotionDetection(false)), T0.plusSeconds(4));

        assertEquals(List.of(new MovementEvent(true, T0), new MovementEvent(true, T0.plusSeconds(2)),
                new MovementEvent(false, T0.plusSeconds(4))), seen);
        assertEquals(new MovementEvent(false, T0.plusSeconds(4)), pet.lastMovement().orElseThrow());
        List<String> logged = platform.logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT)
                .map(e -> e.message()).toList();
        assertEquals(List.of("pet movement detected", "no pet movement"), logged);
        assertEquals(0, bus.sent.size(), "a pet collar is never sent anything");
    }

    @Test
    void hasNoWritableParameterButName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> pet.setParameter("lastMovement", "now"));
        assertEquals("unknown or read-only parameter 'lastMovement' of AmicaPetMovement; writable: name, room",
                e.getMessage());
    }
}

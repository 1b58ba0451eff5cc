package org.tinysep.amica.movement.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.tinysep.device.support.testing.TestPlatform.T0;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.device.support.testing.FakeAmicaBus;
import org.tinysep.device.support.testing.TestPlatform;

/** Movement Detection payloads in, movement reports out. */
class AmicaMovementDeviceTest {

    private final FakeAmicaBus bus = new FakeAmicaBus("1.17", "movement", "door");

    private final TestPlatform platform = new TestPlatform();
    private final AmicaMovementDevice movement = new AmicaMovementDevice(platform.context("AmicaMovement"), bus);

    @Test
    void everyMotionReportIsPassedOnAndOtherPayloadsOfTheNodeAreIgnored() {
        List<MovementEvent> seen = new ArrayList<>();
        movement.connect((src, e) -> seen.add(e));

        movement.payloadReceived(bus, AmicaPayloads.encode(new MotionDetection(true)), T0);
        movement.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(true)), T0.plusSeconds(1));
        movement.payloadReceived(bus, AmicaPayloads.encode(new MotionDetection(true)), T0.plusSeconds(2));
        movement.payloadReceived(bus, AmicaPayloads.encode(new MotionDetection(false)), T0.plusSeconds(4));

        assertEquals(List.of(new MovementEvent(true, T0), new MovementEvent(true, T0.plusSeconds(2)),
                new MovementEvent(false, T0.plusSeconds(4))), seen);
        assertEquals(new MovementEvent(false, T0.plusSeconds(4)), movement.lastMovement().orElseThrow());
        long logged = platform.logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT).count();
        assertEquals(2, logged, "the event log gets changes only: motion, then no motion");
    }

    @Test
    void locationChangeIsValidatedAndAnnounced() {
        List<MovementLocation> seen = new ArrayList<>();
        movement.connect(new org.tinysep.api.sensor.MovementListener() {
            @Override
            public void movementReported(org.tinysep.api.sensor.MovementProvider source, MovementEvent m) {
            }

            @Override
            public void locationChanged(org.tinysep.api.sensor.MovementProvider source, MovementLocation l,
                    Instant at) {
                seen.add(l);
            }
        });
        movement.setParameter("location", "outside");
        assertThrows(IllegalArgumentException.class, () -> movement.setParameter("location", "garden"));
        assertEquals(List.of(MovementLocation.OUTSIDE), seen);
        assertEquals(MovementLocation.OUTSIDE, movement.location());
    }
}

package org.tinysep.itests.time;

import static org.junit.Assert.assertEquals;

import java.time.Instant;
import java.time.temporal.ChronoUnit;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;

/**
 * A component ticking in virtual time through the support library's PlatformTicker: Flat Occupancy's 600 s leave
 * check, driven by synchroniser TICKs instead of real seconds, with a real AmICA door node over UDP. Nothing
 * sleeps: each assertion follows a DONE, after which every listener has run.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class FlatOccupancyVirtualTimeTest extends TimeTestSupport {

    @Override
    String initialMode() {
        return "EXTERNAL";
    }

    @Test
    public void theLeaveCheckEndsExactlyAtCloseTimePlus600VirtualSeconds() throws Exception {
        TimeControllerProvider clock = clock();
        assertEquals(ClockMode.EXTERNAL, clock.mode());
        try (SyncPeer sync = new SyncPeer(syncPort());
                AmicaNode door = new AmicaNode(1, 20, udpPortOf("BusRadioAmicaUdp"), AmicaNodeType.DOOR)) {
            Instant t = clock.now().truncatedTo(ChronoUnit.SECONDS).plusSeconds(86_400); // tomorrow, virtually
            sync.tickDone(t);

            door.keepAlive();
            DoorProvider doorProvider = awaitService(DoorProvider.class, null, TIMEOUT);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            door.door(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "the door opening to make the flat OCCUPIED");
            door.door(false);
            // frames and TICKs travel on different sockets: wait until the close is processed (docs/time-sync.md)
            await(TIMEOUT, () -> doorProvider.state() == OpenState.CLOSED, "the door close to be processed");
            assertEquals(t, clock.now());

            for (int s = 1; s <= 599; s++) {
                sync.tickDone(t.plusSeconds(s));
            }
            assertEquals("599 s after the close: still OCCUPIED", Occupancy.OCCUPIED, flat.occupancy());

            sync.tickDone(t.plusSeconds(600));
            assertEquals("600 s after the close: UNOCCUPIED at once", Occupancy.UNOCCUPIED, flat.occupancy());
            assertEquals(t.plusSeconds(600), flat.since());
        }
    }

    @Test
    public void aJumpPastTheDeadlineEndsTheLeaveCheckStampedWithTheDeadline() throws Exception {
        TimeControllerProvider clock = clock();
        try (SyncPeer sync = new SyncPeer(syncPort());
                AmicaNode door = new AmicaNode(1, 21, udpPortOf("BusRadioAmicaUdp"), AmicaNodeType.DOOR)) {
            Instant t = clock.now().truncatedTo(ChronoUnit.SECONDS).plusSeconds(3600);
            sync.tickDone(t);
            door.keepAlive();
            DoorProvider doorProvider = awaitService(DoorProvider.class, null, TIMEOUT);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            door.door(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "OCCUPIED");
            door.door(false);
            await(TIMEOUT, () -> doorProvider.state() == OpenState.CLOSED, "the door close to be processed");
            // the door's state changes before its listeners run: wait until Flat Occupancy has started its check
            Device flatDevice = awaitService(Device.class, "(" + DeviceProperties.DEVICE_UID + "=" + flat.deviceUid()
                    + ")", TIMEOUT);
            await(TIMEOUT, () -> flatDevice.parameters().stream().anyMatch(p -> p.key().equals("leaveCheckUntil")
                    && !String.valueOf(p.value()).isEmpty()), "Flat Occupancy's leave check to start");

            Instant later = t.plusSeconds(2 * 3600);
            sync.tickDone(later); // one timeAdvanced for two virtual hours
            assertEquals(Occupancy.UNOCCUPIED, flat.occupancy());
            assertEquals(t.plusSeconds(600), flat.since());
        }
    }
}

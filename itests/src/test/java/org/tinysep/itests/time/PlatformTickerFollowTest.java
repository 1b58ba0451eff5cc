package org.tinysep.itests.time;

import static org.junit.Assert.assertEquals;

import java.time.Duration;
import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.Bundle;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;

/**
 * The support library's PlatformTicker (inside Flat Occupancy) follows the Time Controller as it comes and goes:
 * virtual ticks while it is there, its own real-second ticks when it is stopped, virtual ticks again when it is
 * back — with no change to Flat Occupancy. The leave check is shortened to 10 s for this.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class PlatformTickerFollowTest extends TimeTestSupport {

    @Override
    String initialMode() {
        return "EXTERNAL";
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>(super.initialConfigurations());
        configs.put("org.tinysep.flatoccupancy", Map.of("leaveTimeoutSeconds", "10", "exitGraceSeconds", "0"));
        return configs;
    }

    private Bundle timeBundle() {
        for (Bundle b : context.getBundles()) {
            if ("org.tinysep.timecontroller".equals(b.getSymbolicName())) {
                return b;
            }
        }
        throw new AssertionError("org.tinysep.timecontroller is not installed");
    }

    @Test
    public void tickerFallsBackToRealSecondsWithoutTheControllerAndFollowsItAgainWhenBack() throws Exception {
        try (AmicaNode door = new AmicaNode(1, 20, udpPortOf("BusRadioAmicaUdp"), AmicaNodeType.DOOR)) {
            door.keepAlive();
            DoorProvider doorProvider = awaitService(DoorProvider.class, null, TIMEOUT);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);

            // 1. controller present, clock held: no real second ends the leave check, a TICK does
            leaveCheckEndsOnTick(door, doorProvider, flat);

            // 2. controller stopped: the ticker's own scheduler ticks in real time and ends a leave check by itself
            timeBundle().stop();
            await(TIMEOUT, () -> context.getServiceReference(TimeControllerProvider.class) == null, "no clock");
            door.door(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "OCCUPIED");
            door.door(false);
            await(TIMEOUT, () -> doorProvider.state() == OpenState.CLOSED, "the close to be processed");
            Instant closedAbout = Instant.now();
            await(Duration.ofSeconds(30), () -> flat.occupancy() == Occupancy.UNOCCUPIED,
                    "UNOCCUPIED about 10 real seconds after the close, from the ticker's own ticks");
            long waited = Duration.between(closedAbout, Instant.now()).toMillis();
            System.out.printf("PlatformTicker fallback: leave check of 10 s ended %d ms after the close%n", waited);

            // 3. controller back (EXTERNAL from its configuration): the ticker follows its TICKs again
            timeBundle().start();
            leaveCheckEndsOnTick(door, doorProvider, flat);
        }
    }

    private void leaveCheckEndsOnTick(AmicaNode door, DoorProvider doorProvider, FlatOccupancyProvider flat)
            throws Exception {
        TimeControllerProvider clock = clock();
        assertEquals(ClockMode.EXTERNAL, clock.mode());
        try (SyncPeer sync = new SyncPeer(syncPort())) {
            door.door(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "OCCUPIED");
            door.door(false);
            await(TIMEOUT, () -> doorProvider.state() == OpenState.CLOSED, "the close to be processed");
            Instant closed = clock.now();
            sync.tickDone(closed.plusSeconds(9));
            assertEquals(Occupancy.OCCUPIED, flat.occupancy());
            sync.tickDone(closed.plusSeconds(10));
            assertEquals("ended by the TICK itself, before its DONE", Occupancy.UNOCCUPIED, flat.occupancy());
            assertEquals(closed.plusSeconds(10), flat.since());
        }
    }
}

package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.AllocationMeter;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.testing.FakePlacements;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.LearningSettings;
import org.tinysep.inactivity.internal.learn.SleepRule;

/**
 * Issue 29, item 1: what one movement report costs Inactivity Recognition on the radio's delivery thread (65 % of
 * it at the throughput limit), in bytes allocated per report: a home with learned limits, a placed sensor reporting
 * every 100 ms, no worn node. The learner's own bookkeeping (every activity is learned from) stays; what is built
 * per report for nothing (the room found anew, a description's closure when the state does not change) is not.
 */
class MovementReportCostTest {

    private static final Instant T0 = Instant.parse("2026-11-23T09:00:00Z");
    /** A home's zone as configured (a region: a fixed offset's rules are a new object per question in Java 17). */
    private static final ZoneId HOME = ZoneId.of("Europe/Zurich");
    private Instant now = T0;
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final FakePlacements directory = new FakePlacements();
    private final InactivityDevice device = new InactivityDevice(
            new DriverContext(null, "d", "InactivityRecognition", logs.reporter(), new PlatformClock(() -> now)),
            directory, LimitTable.parse(120, "Bathroom=45", ""), new AlertMail(ZoneOffset.UTC),
            LimitPolicy.learned(new LearnedLimits(new HistoryLearner(HOME,
                    new SleepRule(21, 7, HOME), LearningSettings.defaults()))), null);
    private final Fakes.Movement bath = new Fakes.Movement("m-bath");

    MovementReportCostTest() {
        directory.rooms.put("m-bath", "r-bath");
        directory.names.put("m-bath", "Bath sensor");
        HouseInformationProvider house = new FakeHouse(new Room("r-bath", "Bathroom", "Bathroom", Set.of()));
        device.use(house);
        device.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        device.watch(bath);
    }

    @Test
    void aMovementReportAllocatesLittle() {
        bath.report(true, now); // starts the watch
        double bytes = AllocationMeter.bytesPerCall(20_000, () -> {
            now = now.plusMillis(100);
            bath.report(true, now);
        });
        // 1,496 bytes before issue 29's levers here, 880 with a home without wearers asking nobody, ~512 after
        // session 33, 240 after session 34 (one clock read, no Instant to ask whether the clock went back, no
        // closures per report, the zone's offset kept until its next transition)
        assertTrue(bytes < 320, "bytes allocated per movement report: " + bytes);
        assertEquals(InactivityState.WATCHING, device.state());
    }
}

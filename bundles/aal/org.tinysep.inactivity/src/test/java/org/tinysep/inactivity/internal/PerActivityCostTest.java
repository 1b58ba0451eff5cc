package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.time.ZoneOffset;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.testing.FakePlacements;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.LearningSettings;
import org.tinysep.inactivity.internal.learn.SleepRule;

/**
 * Issue 29 item 1: an activity's description names its device, a look-up in the service registry (21 % of the
 * radio thread). It is built when read (a state change's event line, an alert), not per activity; a device
 * without a room is looked up at most once per {@link UnplacedNames#REFRESH_NANOS}, not per activity.
 */
class PerActivityCostTest {

    private static final Instant T0 = Instant.parse("2026-11-22T09:00:00Z");
    private Instant now = T0;
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final AtomicInteger lookups = new AtomicInteger();
    private final FakePlacements directory = new FakePlacements() {
        @Override
        public String nameOf(String deviceUid) {
            lookups.incrementAndGet();
            return super.nameOf(deviceUid);
        }
    };
    private final InactivityDevice device = new InactivityDevice(
            new DriverContext(null, "d", "InactivityRecognition", logs.reporter(), new PlatformClock(() -> now)),
            directory, LimitTable.parse(120, "Bathroom=45", ""), new AlertMail(ZoneOffset.UTC),
            LimitPolicy.learned(new LearnedLimits(new HistoryLearner(ZoneOffset.UTC,
                    new SleepRule(21, 7, ZoneOffset.UTC), LearningSettings.defaults()))), null);
    private final Fakes.Movement bath = new Fakes.Movement("m-bath");
    private final Fakes.Movement loose = new Fakes.Movement("m-loose");

    PerActivityCostTest() {
        directory.rooms.put("m-bath", "r-bath");
        directory.names.put("m-bath", "Bath sensor");
        directory.names.put("m-loose", "Loose sensor");
        HouseInformationProvider house = new FakeHouse(new Room("r-bath", "Bathroom", "Bathroom",
                Set.of()));
        device.use(house);
        device.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        device.watch(bath);
        device.watch(loose);
    }

    @Test
    void thousandActivitiesOfAPlacedSensorLookUpNoName() {
        bath.report(true, now); // the first one starts the watch: its state change names the activity
        int afterFirst = lookups.get();
        for (int i = 0; i < 1_000; i++) {
            now = now.plusMillis(100);
            bath.report(true, now);
        }
        int per1000 = lookups.get() - afterFirst;
        assertTrue(per1000 <= 2, "name look-ups per 1,000 activities (at most a backup's save): " + per1000);
        assertEquals("movement by Bath sensor", alertAfterTheLimit().lastActivity(), "read when needed");
    }

    @Test
    void thousandActivitiesOfAnUnplacedSensorLookUpItsNameOnce() {
        for (int i = 0; i < 1_000; i++) {
            now = now.plusMillis(100);
            loose.report(true, now);
        }
        assertTrue(lookups.get() <= 3, "name look-ups per 1,000 activities of a device without a room: "
                + lookups.get());
        InactivityAlert alert = alertAfterTheLimit();
        assertEquals("movement by Loose sensor", alert.lastActivity());
        assertEquals("unknown room (device Loose sensor)", alert.roomName());
    }

    /** Lets the platform's time run past the last activity's limit (the default, 120 min). */
    private InactivityAlert alertAfterTheLimit() {
        Instant until = now.plusSeconds(121 * 60);
        while (now.isBefore(until)) {
            now = now.plusSeconds(1);
            device.tick(now);
        }
        assertEquals(InactivityState.ALERT, device.state());
        return device.alert().orElseThrow();
    }
}

package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.AllocationMeter;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.testing.FakePlacements;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.inactivity.internal.person.PersonAlertWords;
import org.tinysep.inactivity.internal.person.WearerSettings;
import org.tinysep.inactivity.internal.person.Wearers;

/**
 * Issue 29, item 1: work Inactivity Recognition did per movement report on the radio's delivery thread that a
 * report does not need, counted: the platform's clock read twice (each time through the Time Controller's lock),
 * the backup's throttle looked at twice, and the wearers' lock taken in a home without wearers (where a wearer's
 * alert being handed on, under that lock, would hold up the radio).
 */
class PerReportWorkTest {

    private static final Instant T0 = Instant.parse("2026-11-23T09:00:00Z");
    private static final Duration TWO_HOURS = Duration.ofMinutes(120);
    private Instant now = T0;

    @Test
    void aMovementReportReadsThePlatformsClockOnce() {
        AtomicInteger reads = new AtomicInteger();
        FakePlacements directory = new FakePlacements();
        directory.rooms.put("m-bath", "r-bath");
        directory.names.put("m-bath", "Bath sensor");
        InactivityDevice device = new InactivityDevice(
                new DriverContext(null, "d", "InactivityRecognition", new RecordingLogs(() -> now).reporter(),
                        new PlatformClock(() -> {
                            reads.incrementAndGet();
                            return now;
                        })),
                directory, LimitTable.parse(120, "Bathroom=45", ""), new AlertMail(ZoneOffset.UTC));
        device.use(new FakeHouse(new Room("r-bath", "Bathroom", "Bathroom", Set.of())));
        device.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        Fakes.Movement bath = new Fakes.Movement("m-bath");
        device.watch(bath);
        bath.report(true, now); // starts the watch
        int before = reads.get();
        for (int i = 0; i < 1_000; i++) {
            now = now.plusMillis(100);
            bath.report(true, now);
        }
        assertEquals(1_000, reads.get() - before, "platform clock reads per 1,000 movement reports");
        assertEquals(InactivityState.WATCHING, device.state());
        assertEquals(Optional.of(now.plus(Duration.ofMinutes(45))), deadline(device));
    }

    @Test
    void aRoomActivityLooksAtTheBackupOnce() {
        AtomicInteger looks = new AtomicInteger();
        List<String> events = new ArrayList<>();
        DeviceSide side = new DeviceSide(events::add, () -> { }, looks::incrementAndGet, (s, detail) -> { },
                (s, at) -> { });
        InactivityLogic logic = new InactivityLogic(TWO_HOURS, T0);
        AlertMail words = new AlertMail(ZoneOffset.UTC);
        HelpCall help = new HelpCall(words, NO_DESK);
        PersonWatches persons = persons(help);
        RoomActivity rooms = new RoomActivity();
        ActivityFeed feed = new ActivityFeed(logic, rooms, LimitPolicy.thesis(), words, () -> persons,
                new StateAnnouncer(logic, help, words, () -> persons, side), side);
        feed.occupancy(Occupancy.OCCUPIED, T0);
        looks.set(0);
        for (int i = 1; i <= 1_000; i++) {
            now = T0.plusMillis(100L * i);
            feed.activity(new Activity("r-bath", "Bathroom", "movement by Bath sensor", now, TWO_HOURS), now);
        }
        assertEquals(1_000, looks.get(), "looks at the backup's throttle per 1,000 room activities");
        assertEquals(List.of("inactivity watching (flat occupied)"), events);
        assertEquals("{r-bath=" + now + "}", rooms.describe());
    }

    @Test
    void aRoomActivityWithoutWearersDoesNotWaitForTheWearersLock() throws Exception {
        PersonWatches persons = persons(new HelpCall(new AlertMail(ZoneOffset.UTC), NO_DESK));
        CountDownLatch held = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        ExecutorService other = Executors.newSingleThreadExecutor();
        try {
            other.submit(() -> {
                synchronized (persons) { // as while a wearer's alert is handed on
                    held.countDown();
                    release.await();
                }
                return null;
            });
            held.await();
            List<String> said = assertTimeoutPreemptively(Duration.ofSeconds(10), () -> persons.room(
                    new Activity("r-bath", "Bathroom", "movement by Bath sensor", T0, TWO_HOURS), T0),
                    "a room activity in a home without wearers waited for the wearers' lock");
            assertEquals(List.of(), said);
        } finally {
            release.countDown();
            other.shutdown();
            other.awaitTermination(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void askingWhetherTheClockWentBackAllocatesNothing() {
        InactivityLogic logic = new InactivityLogic(TWO_HOURS, T0);
        logic.occupancy(Occupancy.OCCUPIED, T0);
        logic.activity(new Activity("r-bath", "Bathroom", "movement by Bath sensor", T0, TWO_HOURS));
        Instant later = T0.plusSeconds(1);
        double bytes = AllocationMeter.bytesPerCall(20_000, () -> logic.rebase(later));
        assertTrue(bytes < 8, "bytes allocated per activity to ask whether the clock went back: " + bytes);
        assertEquals(Optional.of(T0), logic.rebase(T0.minusSeconds(10)), "the clock went back 10 s from T0");
    }

    @Test
    void aheadMeansLaterThanNowPlusTheSlack() {
        Random r = new Random(29);
        for (int k = 0; k < 100_000; k++) {
            Instant now = T0.plusNanos(r.nextLong(1_000_000_000_000L));
            Instant t = now.plusNanos(r.nextInt(3) == 0 ? 2_000_000_000L + r.nextInt(3) - 1
                    : r.nextLong(8_000_000_000L) - 4_000_000_000L);
            assertEquals(t.isAfter(now.plus(InactivityLogic.CLOCK_SLACK)), InactivityLogic.ahead(t, now),
                    t + " vs " + now);
        }
    }

    private static final HelpCall.AlertDesk NO_DESK = new HelpCall.AlertDesk() {
        @Override
        public <T> Optional<T> use(Function<AlertService, T> use) {
            return Optional.empty();
        }
    };

    private static PersonWatches persons(HelpCall help) {
        PersonAlertWords w = new PersonAlertWords(ZoneOffset.UTC);
        return new PersonWatches(new Wearers(WearerSettings.defaults(), w::time), w, TWO_HOURS, NO_DESK,
                help::mailer);
    }

    private static Optional<Instant> deadline(InactivityDevice device) {
        return device.parameters().stream().filter(p -> p.key().equals("deadline")).findFirst()
                .map(p -> Instant.parse(String.valueOf(p.value())));
    }
}

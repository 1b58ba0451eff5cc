package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Clock;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Connection;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.TimeControllerListener;
import org.tinysep.api.service.TimeControllerProvider;

class LogServicesTest {

    static final Instant SYSTEM = Instant.parse("2026-11-22T10:00:00Z");
    static final Clock FIXED = Clock.fixed(SYSTEM, ZoneOffset.UTC);

    /** A Time Controller in external mode, showing a fixed simulated time. */
    record FakeTimeController(Instant now) implements TimeControllerProvider {
        @Override
        public ClockMode mode() {
            return ClockMode.EXTERNAL;
        }

        @Override
        public String deviceUid() {
            return "time-controller";
        }

        @Override
        public Connection connect(TimeControllerListener listener) {
            throw new UnsupportedOperationException();
        }
    }

    private final List<EventEntry> echoed = new ArrayList<>();

    private EventLogService events(int capacity) {
        EventLogService log = new EventLogService(FIXED);
        log.start(() -> capacity, Runnable::run, echoed::add);
        return log;
    }

    @Test
    void eventsAreStampedWithTheFallbackClockAndNumbered() {
        EventLogService log = events(10);
        log.record(EventKind.DRIVER_ADDED, "amica-movement", "driver AmicaMovement added");
        log.record(EventKind.DEVICE_CREATED, "amica-movement-0012", "created");
        List<EventEntry> recent = log.recent(10);
        assertEquals(2, recent.size());
        assertEquals(1, recent.get(0).sequence());
        assertEquals(2, recent.get(1).sequence());
        assertEquals(SYSTEM, recent.get(0).time());
        assertEquals("amica-movement-0012", recent.get(1).origin());
    }

    @Test
    void timeComesFromTheTimeControllerWhileOneIsBound() {
        EventLogService log = events(10);
        Instant simulated = Instant.parse("2011-06-01T08:00:00Z");
        FakeTimeController first = new FakeTimeController(simulated);
        log.bindTimeController(first);
        log.record(EventKind.STATUS, "x", "during simulation");
        FakeTimeController second = new FakeTimeController(simulated.plusSeconds(60));
        log.bindTimeController(second); // greedy: the better one is bound before the old one is unbound
        log.unbindTimeController(first);
        log.record(EventKind.STATUS, "x", "still simulated");
        log.unbindTimeController(second);
        log.record(EventKind.STATUS, "x", "back to the system clock");
        List<Instant> times = log.recent(3).stream().map(EventEntry::time).toList();
        assertEquals(List.of(simulated, simulated.plusSeconds(60), SYSTEM), times);
    }

    @Test
    void aBrokenTimeControllerFallsBackToTheSystemClock() {
        EventLogService log = events(10);
        log.bindTimeController(new FakeTimeController(null));
        log.record(EventKind.STATUS, "x", "no time from the controller");
        assertEquals(SYSTEM, log.recent(1).get(0).time());
    }

    @Test
    void everyEntryIsEchoedInOrderOnTheSinkExecutor() {
        EventLogService log = events(10);
        log.record(EventKind.DEVICE_EVENT, "door-1", "door opened");
        log.record(null, "door-1", "kind missing");
        assertEquals(List.of("door opened", "kind missing"), echoed.stream().map(EventEntry::message).toList());
        assertEquals(EventKind.PROBLEM, echoed.get(1).kind());
    }

    @Test
    void badCapacitiesAreIgnoredAndGoodOnesApplied() {
        EventLogService log = events(10);
        log.configure(() -> 0);
        assertEquals(10, log.capacity());
        log.configure(() -> {
            throw new NumberFormatException("For input string: \"many\"");
        });
        assertEquals(10, log.capacity());
        log.configure(() -> 3);
        assertEquals(3, log.capacity());
        for (int i = 0; i < 5; i++) {
            log.record(EventKind.STATUS, "x", "m" + i);
        }
        assertEquals(List.of(3L, 4L, 5L), log.recent(10).stream().map(EventEntry::sequence).toList());
    }

    @Test
    void packetsKeepACopyOfTheirBytesAndTheirTime() {
        PacketLogService log = new PacketLogService(FIXED);
        log.configure(() -> 2);
        byte[] bytes = {(byte) 170, 1, (byte) 255};
        log.record(Direction.RECEIVED, "busradio-amica 127.0.0.1:5000", bytes, "");
        bytes[0] = 0;
        log.record(Direction.SENT, "busradio-amica", new byte[] {2}, "");
        log.record(Direction.RECEIVED, "busradio-amica", null, "truncated frame");
        List<PacketEntry> recent = log.recent(5);
        assertEquals(List.of(2L, 3L), recent.stream().map(PacketEntry::sequence).toList());
        assertEquals("truncated frame", recent.get(1).note());
        assertEquals(SYSTEM, recent.get(0).time());

        PacketLogService other = new PacketLogService(FIXED);
        other.configure(() -> 5);
        other.record(Direction.RECEIVED, "o", bytes, "");
        bytes[1] = 9;
        assertArrayEquals(new byte[] {0, 1, (byte) 255}, other.recent(1).get(0).bytes());
        assertTrue(other.recent(0).isEmpty());
    }
}

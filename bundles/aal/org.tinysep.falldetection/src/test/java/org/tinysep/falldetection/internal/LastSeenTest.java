package org.tinysep.falldetection.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Connection;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.rooms.Placements;

/** Where the person was last seen: the newest indoor activity's room, by name, in the FALL alert's words. */
class LastSeenTest {

    static final Instant T = Instant.parse("2026-03-02T14:02:10Z");
    private final Map<String, String> placed = Map.of("kitchen-pir", "r-kitchen", "hall-door", "r-hall",
            "garden-pir", "r-garden", "odd-pir", "r-gone");

    private final AtomicInteger lookups = new AtomicInteger();
    private final LastSeen seen = new LastSeen(new Placements() {
        @Override
        public Optional<String> roomOf(String deviceUid) {
            lookups.incrementAndGet();
            return Optional.ofNullable(placed.get(deviceUid));
        }

        @Override
        public String nameOf(String deviceUid) {
            lookups.incrementAndGet();
            return "Sensor " + deviceUid;
        }
    });

    LastSeenTest() {
        seen.rooms(List.of(new Room("r-kitchen", "Kitchen", "Kitchen", Set.of()),
                new Room("r-hall", "Hall", "Hall", Set.of()), new Room("r-garden", "Garden", "Garden", Set.of())));
    }

    @Test
    void theNewestIndoorMotionNamesTheRoomAndTheTimeInTheAlertsWords() {
        FallWords words = new FallWords(ZoneOffset.UTC);
        assertEquals(Optional.empty(), seen.last());
        assertTrue(words.where(seen.last()).startsWith("no room seen yet"), words.where(seen.last()));
        seen.movementReported(pir("kitchen-pir", MovementLocation.INSIDE), new MovementEvent(true, T));
        seen.movementReported(pir("kitchen-pir", MovementLocation.INSIDE), new MovementEvent(false, T.plusSeconds(60)));
        seen.movementReported(pir("garden-pir", MovementLocation.OUTSIDE), new MovementEvent(true, T.plusSeconds(90)));
        assertEquals("last seen in the Kitchen at 14:02 by its motion sensor", words.where(seen.last()));
    }

    @Test
    void aDoorChangeCountsItsFirstReportAndLateReportsDoNot() {
        DoorListener l = seen;
        l.doorChanged(door("hall-door"), OpenState.CLOSED, true, T.plusSeconds(300)); // resting state after a start
        assertEquals(Optional.empty(), seen.last());
        seen.movementReported(pir("kitchen-pir", MovementLocation.INSIDE), new MovementEvent(true, T));
        l.doorChanged(door("hall-door"), OpenState.OPEN, false, T.plusSeconds(120));
        assertEquals("last seen in the Hall at 14:04 by its door sensor (door open)",
                new FallWords(ZoneOffset.UTC).where(seen.last()));
        seen.movementReported(pir("kitchen-pir", MovementLocation.INSIDE), new MovementEvent(true, T.plusSeconds(5)));
        assertEquals("the Hall", seen.last().orElseThrow().room(), "a late report does not move the person back");
    }

    @Test
    void anUnplacedSensorOrAnUnknownRoomIsSaidSo() {
        seen.movementReported(pir("loose-pir", MovementLocation.INSIDE), new MovementEvent(true, T));
        assertEquals("an unknown room (device Sensor loose-pir is not placed in a room)", seen.last().orElseThrow().room());
        seen.movementReported(pir("odd-pir", MovementLocation.INSIDE), new MovementEvent(true, T.plusSeconds(1)));
        assertEquals("room r-gone", seen.last().orElseThrow().room());
    }

    @Test
    void aReportLooksNothingUpOnlyTheAlertDoes() {
        for (int i = 0; i < 1_000; i++) { // on the radio's delivery thread: no placement or name lookup per report
            seen.movementReported(pir(i % 2 == 0 ? "loose-pir" : "kitchen-pir", MovementLocation.INSIDE),
                    new MovementEvent(true, T.plusMillis(i)));
        }
        assertEquals(0, lookups.get(), "lookups for 1,000 motion reports");
        assertEquals("the Kitchen", seen.last().orElseThrow().room());
        assertTrue(lookups.get() <= 2, "lookups when the alert asks: " + lookups.get());
    }

    static MovementProvider pir(String uid, MovementLocation where) {
        return new MovementProvider() {
            @Override
            public String deviceUid() {
                return uid;
            }

            @Override
            public Connection connect(MovementListener listener) {
                throw new UnsupportedOperationException();
            }

            @Override
            public Optional<MovementEvent> lastMovement() {
                return Optional.empty();
            }

            @Override
            public MovementLocation location() {
                return where;
            }
        };
    }

    private static DoorProvider door(String uid) {
        return (DoorProvider) java.lang.reflect.Proxy.newProxyInstance(LastSeenTest.class.getClassLoader(),
                new Class<?>[] {DoorProvider.class}, (p, m, a) -> m.getName().equals("deviceUid") ? uid : null);
    }
}

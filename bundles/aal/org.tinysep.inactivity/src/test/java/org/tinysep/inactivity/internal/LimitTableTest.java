package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.Room;

/** Limits: room override (uid, name, type) beats type default beats the general default; bad entries skipped. */
class LimitTableTest {

    private static Room room(String uid, String name, String type) {
        return new Room(uid, name, type, Set.of());
    }

    @Test
    void defaultsPerRoomType() {
        InactivityConfig c = new InactivityConfigDefaults();
        LimitTable t = LimitTable.parse(c.defaultLimitMinutes(), c.typeLimits(), c.roomLimits());
        assertEquals(Duration.ofMinutes(45), t.limitFor(room("a", "Small bath", "bathroom")));
        assertEquals(Duration.ofMinutes(600), t.limitFor(room("b", "Master", "Bedroom")));
        assertEquals(Duration.ofMinutes(180), t.limitFor(room("c", "Lounge", "Living room")));
        assertEquals(Duration.ofMinutes(120), t.limitFor(room("d", "Store", "Storage")));
        assertEquals(List.of(), t.problems());
    }

    @Test
    void overridesByUidNameAndType() {
        LimitTable t = LimitTable.parse(100, "Bathroom=45", "Bathroom=30, uid-2=20, Guest bath=25");
        assertEquals(Duration.ofMinutes(30), t.limitFor(room("uid-1", "Bath", "Bathroom")));
        assertEquals(Duration.ofMinutes(20), t.limitFor(room("uid-2", "Guest bath", "Bathroom")));
        assertEquals(Duration.ofMinutes(25), t.limitFor(room("uid-3", "guest BATH", "Bathroom")));
        assertEquals(Duration.ofMinutes(20), t.limitForUnknownRoom("uid-2"));
        assertEquals(Duration.ofMinutes(100), t.limitForUnknownRoom("uid-9"));
    }

    @Test
    void badEntriesAreSkippedWithAMessage() {
        LimitTable t = LimitTable.parse(0, "Kitchen=ninety, Hall=30", "=5, Bathroom=-1, Attic");
        assertEquals(Duration.ofMinutes(120), t.defaultLimit());
        assertEquals(Duration.ofMinutes(30), t.limitFor(room("h", "Hall", "Hall")));
        assertEquals(Duration.ofMinutes(120), t.limitFor(room("k", "Kitchen", "Kitchen")));
        assertEquals(List.of("defaultLimitMinutes must be at least 1, was 0; using 120",
                "typeLimits: ignored 'Kitchen=ninety' (write room=minutes, minutes at least 1)",
                "roomLimits: ignored '=5' (write room=minutes, minutes at least 1)",
                "roomLimits: ignored 'Bathroom=-1' (write room=minutes, minutes at least 1)",
                "roomLimits: ignored 'Attic' (write room=minutes, minutes at least 1)"), t.problems());
    }
}

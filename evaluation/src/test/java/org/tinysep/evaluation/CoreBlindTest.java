package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Issue 28: blind time in the core replay — a collapse while the flat counts as empty is one nobody watches. */
class CoreBlindTest {

    private static final Instant T = Instant.parse("2011-12-01T10:00:00Z");

    private static CoreReplay.Act indoor(int minutes) {
        return new CoreReplay.Act(T.plusSeconds(60L * minutes), "Kitchen", "Cupboard on", false, false);
    }

    private static CoreReplay.Act outerDoor(int minutes, boolean closes) {
        return new CoreReplay.Act(T.plusSeconds(60L * minutes), "Entrance", "Maindoor " + (closes ? "off" : "on"),
                closes, true);
    }

    @Test
    void afterTheOuterDoorClosedAndTenQuietMinutesItIsBlind() {
        List<CoreReplay.Act> left = List.of(indoor(0), outerDoor(5, false), outerDoor(6, true));
        assertFalse(CoreReplay.blindAt(left, T.plusSeconds(60 * 10)), "4 min after the door closed: still watched");
        assertTrue(CoreReplay.blindAt(left, T.plusSeconds(60 * 30)), "24 min after it: the flat counts as empty");
    }

    @Test
    void activityIndoorsAfterTheDoorKeepsItWatched() {
        List<CoreReplay.Act> cameIn = List.of(outerDoor(5, false), outerDoor(6, true), indoor(8));
        assertFalse(CoreReplay.blindAt(cameIn, T.plusSeconds(60 * 30)), "someone moved inside after the door");
        List<CoreReplay.Act> back = List.of(outerDoor(5, false), outerDoor(6, true), outerDoor(60, false), indoor(61));
        assertFalse(CoreReplay.blindAt(back, T.plusSeconds(60 * 90)), "came back home: watched again");
        assertTrue(CoreReplay.blindAt(back, T.plusSeconds(60 * 40)), "in between: empty");
    }
}

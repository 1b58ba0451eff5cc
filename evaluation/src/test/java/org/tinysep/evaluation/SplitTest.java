package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.simulator.replay.Kind;
import org.tinysep.simulator.replay.SensorEvent;

/** The history/test splits of the harness: the headline half split and cross-validation by days. */
class SplitTest {

    /** 10 days, an event every 6 hours from 2011-11-28 03:00. */
    private static Home tenDays() {
        List<SensorEvent> events = new ArrayList<>();
        LocalDateTime t = LocalDateTime.parse("2011-11-28T03:00:00");
        for (int i = 0; i < 40; i++) {
            events.add(new SensorEvent(t.plusHours(6L * i), "Seat", "Living", Kind.PRESSURE, i % 2 == 0));
        }
        return new Home("h", events, List.of(), Path.of("m"), Path.of("h.xml"), List.of());
    }

    @Test
    void halfLearnsFromTheFirstHalfAndTestsTheSecond() {
        Home h = tenDays();
        Split s = Split.of("half", h);
        assertEquals(1, s.folds().size());
        Split.Fold f = s.folds().get(0);
        assertTrue(f.history().stream().allMatch(e -> e.time().isBefore(h.split())));
        assertEquals(0, f.extraDays());
        List<Split.TestSegment> t = Split.testSegments(h, f);
        assertEquals(1, t.size());
        assertEquals(40 - f.history().size(), t.get(0).events().size(), "every event from the middle on, the last too");
    }

    @Test
    void crossValidationTestsEveryDayOnceAndLearnsFromTheOtherDays() {
        Home h = tenDays();
        Split s = Split.of("cv3", h);
        assertEquals(3, s.folds().size());
        int tested = 0;
        for (Split.Fold f : s.folds()) {
            for (Split.TestSegment seg : Split.testSegments(h, f)) {
                List<SensorEvent> own = seg.events().stream().filter(e -> f.covers(e.time())).toList();
                tested += own.size();
                assertTrue(own.stream().noneMatch(f.history()::contains), "a test day is never history of its fold");
                assertTrue(seg.events().size() <= own.size() + 1, "at most the next day's first event is added");
            }
            assertEquals(14, f.extraDays(), "test days replayed whole weeks after the 10-day recording");
            assertEquals(40, f.history().size() + h.events().stream().filter(e -> f.covers(e.time())).count());
        }
        assertEquals(40, tested, "every event tested exactly once");
        assertEquals(s.folds().get(1), s.foldOf(LocalDateTime.parse("2011-11-29T12:00:00")), "day 1 -> fold 1");
    }

    @Test
    void aBadSplitIsRefusedInPlainWords() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Split.of("thirds", tenDays()));
        assertTrue(e.getMessage().contains("half or cvK"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Split.of("cv11", tenDays()));
    }
}

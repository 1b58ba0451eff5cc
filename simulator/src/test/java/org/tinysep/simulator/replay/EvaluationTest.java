package org.tinysep.simulator.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.List;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;

/** Interval helpers and the overlap agreement, on hand-made intervals (times in minutes after T). */
class EvaluationTest {

    private static final LocalDateTime T = LocalDateTime.parse("2020-01-01T00:00");

    @Test
    void leavingIntervalsAreMergedAndImproperOnesSkipped() {
        List<Label> labels = List.of(label(10, 20, "Leaving"), label(15, 30, "leaving"), label(40, 35, "Leaving"),
                label(50, 60, "Sleeping"), label(70, 80, "Leaving"));
        assertEquals(List.of(iv(10, 30), iv(70, 80)), Evaluation.leaving(labels));
    }

    @Test
    void agreementIsOverlapOverEachSide() {
        // reference 0-60 and 100-160 (120 min); predicted 30-120 (90 min); overlap 30-60 + 100-120 = 50 min
        Agreement a = Evaluation.agreement(List.of(iv(0, 60), iv(100, 160)), List.of(iv(30, 120)));
        assertEquals(Duration.ofMinutes(120), a.reference());
        assertEquals(Duration.ofMinutes(90), a.predicted());
        assertEquals(Duration.ofMinutes(50), a.overlap());
        assertEquals(50.0 / 120, a.recall(), 1e-12);
        assertEquals(50.0 / 90, a.precision(), 1e-12);
        assertEquals(2 * (50.0 / 120) * (50.0 / 90) / (50.0 / 120 + 50.0 / 90), a.f1(), 1e-12);
    }

    @Test
    void agreementHandlesManySmallPredictionsDuplicatesAndDisjointLists() {
        Agreement a = Evaluation.agreement(List.of(iv(0, 100)),
                List.of(iv(90, 110), iv(10, 20), iv(10, 20), iv(15, 25), iv(200, 210)));
        assertEquals(Duration.ofMinutes(25), a.overlap());
        assertEquals(Duration.ofMinutes(45), a.predicted());
        Agreement none = Evaluation.agreement(List.of(iv(0, 10)), List.of(iv(10, 20)));
        assertEquals(0.0, none.recall());
        assertTrue(Double.isNaN(Evaluation.agreement(List.of(), List.of(iv(0, 1))).recall()));
        assertTrue(Double.isNaN(Evaluation.agreement(List.of(iv(0, 1)), List.of()).precision()));
    }

    @Test
    void stateTimelineBecomesIntervalsAndIsClipped() {
        TreeMap<LocalDateTime, String> changes = new TreeMap<>();
        changes.put(T.plusMinutes(0), "OCCUPIED");
        changes.put(T.plusMinutes(10), "UNOCCUPIED");
        changes.put(T.plusMinutes(20), "UNOCCUPIED");
        changes.put(T.plusMinutes(30), "OCCUPIED");
        changes.put(T.plusMinutes(50), "UNOCCUPIED");
        assertEquals(List.of(iv(10, 30), iv(50, 60)), Evaluation.whileIn(changes, "UNOCCUPIED", T.plusMinutes(60)));
        assertEquals(List.of(iv(25, 30), iv(50, 55)),
                Evaluation.clip(List.of(iv(10, 30), iv(50, 60)), T.plusMinutes(25), T.plusMinutes(55)));
    }

    private static Interval iv(int from, int to) {
        return new Interval(T.plusMinutes(from), T.plusMinutes(to));
    }

    private static Label label(int from, int to, String activity) {
        return new Label(T.plusMinutes(from), T.plusMinutes(to), activity, "");
    }
}

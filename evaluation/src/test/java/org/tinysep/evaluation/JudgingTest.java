package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.simulator.replay.Interval;
import org.tinysep.simulator.replay.Label;

/** The harness's reading of event-log entries and its judging rules, on hand-made entries and labels. */
class JudgingTest {

    private static final long SHIFT = 7;
    private static final LocalDateTime T0 = LocalDateTime.parse("2011-11-28T10:00:00");

    private static LogEntry entry(long seq, String recorded, String message) {
        return new LogEntry(LocalDateTime.parse(recorded).plusDays(SHIFT).toInstant(java.time.ZoneOffset.UTC), seq, "DEVICE_EVENT",
                message);
    }

    @Test
    void timelineReadsAlertsStatesAndOccupancyAndIgnoresTheShutdown() {
        List<LogEntry> entries = List.of(
                // the platform starting: stamped by the wall clock, days before the replay's virtual time
                entry(1, "2011-11-26T16:00:00", "restored after a restart: flat occupied since 2026-12-05T10:00:00Z"),
                entry(2, "2011-11-28T10:01:00", "inactivity watching (flat occupied)"),
                entry(3, "2011-11-28T11:00:00", "inactivity alert (limit reached): TinySEP: no activity in Hall"),
                entry(4, "2011-11-28T12:00:00", "flat unoccupied (no indoor motion for 600 s after the door closed)"),
                entry(5, "2011-11-28T12:00:00", "inactivity not watching (flat unoccupied)"),
                entry(6, "2011-11-26T16:05:00", "inactivity not watching (flat unknown)")); // the platform stopping
        Timeline t = Timeline.of(entries, SHIFT, T0);
        assertEquals(List.of(LocalDateTime.parse("2011-11-28T11:00:00")), t.alerts());
        assertEquals("OCCUPIED", t.occupancy().get(T0), "the restart's entry is the initial state");
        assertEquals("UNOCCUPIED", t.occupancy().floorEntry(LocalDateTime.parse("2011-11-28T13:00:00")).getValue());
        assertFalse(t.watching().get(T0));
        assertTrue(t.watching().floorEntry(LocalDateTime.parse("2011-11-28T11:30:00")).getValue(),
                "an alert is a watching state");
        assertFalse(t.watching().lastEntry().getValue());
        assertEquals(LocalDateTime.parse("2011-11-28T12:00:00"), t.watching().lastKey(),
                "the stopping platform's entry (wall clock, after the replay) is ignored");
    }

    @Test
    void collapsesAreJudgedByTheirQuietPeriod() {
        LocalDateTime quiet = T0;
        LocalDateTime c = T0.plusMinutes(30);
        assertEquals(CollapseResult.Outcome.DETECTED,
                CollapseResult.judge(c, quiet, List.of(T0.minusHours(1), c.plusMinutes(45))).outcome());
        assertEquals(Duration.ofMinutes(45), CollapseResult.judge(c, quiet, List.of(c.plusMinutes(45))).delay());
        assertEquals(CollapseResult.Outcome.ALREADY_ALERTED,
                CollapseResult.judge(c, quiet, List.of(T0.plusMinutes(20), c.plusMinutes(45))).outcome());
        assertEquals(CollapseResult.Outcome.MISSED,
                CollapseResult.judge(c, quiet, List.of(c.plusHours(12).plusSeconds(1))).outcome());
    }

    @Test
    void collapsesLieOnlyInAtHomeAwakeTime() {
        List<Label> labels = List.of(new Label(T0, T0.plusMinutes(20), "Breakfast", ""),
                new Label(T0.plusHours(1), T0.plusHours(2), "Leaving", ""),
                new Label(T0.plusHours(3), T0.plusHours(9), "Sleeping", ""),
                new Label(T0.plusHours(5), T0.plusHours(4), "Toileting", ""), // ends before it starts: skipped
                new Label(T0.plusHours(9).plusMinutes(30), T0.plusHours(10), "Spare_Time/TV", ""));
        List<Interval> free = Collapses.candidates(labels, T0, T0.plusHours(10));
        assertEquals(List.of(new Interval(T0, T0.plusHours(1)), new Interval(T0.plusHours(2), T0.plusHours(3)),
                new Interval(T0.plusHours(9), T0.plusHours(10))), free);
        List<LocalDateTime> drawn = Collapses.draw(free, 500, 1);
        assertEquals(drawn, Collapses.draw(free, 500, 1), "a fixed seed draws the same moments");
        assertTrue(drawn.stream().allMatch(m -> free.stream()
                .anyMatch(i -> !m.isBefore(i.start()) && m.isBefore(i.end()))), "never while away or asleep");
    }

    @Test
    void collapsesLieOnlyWithinTheLabelledSpan() {
        List<Label> labels = List.of(new Label(T0.plusHours(2), T0.plusHours(3), "Lunch", ""),
                new Label(T0.plusHours(4), T0.plusHours(5), "Leaving", ""),
                new Label(T0.plusHours(6), T0.plusHours(7), "Spare_Time/TV", ""),
                new Label(T0.plusHours(9), T0.plusHours(8), "Toileting", "")); // ends before it starts: no span
        assertEquals(List.of(new Interval(T0.plusHours(2), T0.plusHours(4)),
                new Interval(T0.plusHours(5), T0.plusHours(7))), Collapses.candidates(labels, T0, T0.plusHours(10)),
                "nobody says what the resident does before the first label or after the last one");
        assertEquals(List.of(new Interval(T0.plusHours(5), T0.plusHours(6))),
                Collapses.candidates(labels, T0.plusHours(5), T0.plusHours(6)), "the asked range inside the span");
        assertEquals(List.of(), Collapses.candidates(labels, T0.plusHours(7), T0.plusHours(10)), "after the span");
        assertEquals(List.of(), Collapses.candidates(List.of(), T0, T0.plusHours(10)), "no labels, no span");
    }

    @Test
    void falseAlarmsAreSplitByDayAndNightAndBlindTimeIsAtHomeTimeNotWatched() {
        List<LogEntry> entries = List.of(
                entry(1, "2011-11-28T10:00:00", "flat occupied (motion)"),
                entry(2, "2011-11-28T10:00:00", "inactivity watching (flat occupied)"),
                entry(3, "2011-11-28T12:00:00", "inactivity alert (limit reached): x"),
                entry(4, "2011-11-28T23:00:00", "inactivity alert (limit reached): y"),
                entry(5, "2011-11-29T04:00:00", "inactivity not watching (flat unoccupied)"),
                entry(6, "2011-11-29T04:00:00", "flat unoccupied (no indoor motion)"));
        Timeline t = Timeline.of(entries, SHIFT, T0);
        List<Label> labels = List.of(new Label(LocalDateTime.parse("2011-11-29T04:00:00"),
                LocalDateTime.parse("2011-11-29T07:00:00"), "Leaving", ""));
        TestHalfFigures f = TestHalfFigures.of(t, labels, T0, T0.plusDays(1));
        assertEquals(1, f.alertsDay());
        assertEquals(1, f.alertsNight());
        assertEquals(30.0, f.perThirtyDays(1), 1e-9);
        assertEquals(1.0, f.occupancy().recall(), 1e-9);
        assertEquals(0.5, f.occupancy().precision(), 1e-9, "unoccupied 04:00-10:00, away 04:00-07:00");
        assertEquals(3.0 / 21, f.blindShare(), 1e-9, "not watching 07:00-10:00 of 21 h at home");
    }
}

package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.LocalDateTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.simulator.replay.Interval;

/** Issue 28 item 3: "a fall while moving" puts each collapse right after an awake at-home activity. */
class MovingCollapsesTest {

    private static LocalDateTime t(String hhmm) {
        return LocalDateTime.parse("2011-11-28T" + hhmm + ":00");
    }

    @Test
    void everyCollapseFollowsAnAwakeActivityByOneSecond() {
        List<LocalDateTime> acts = List.of(t("06:00"), t("09:00"), t("12:30"), t("23:30"));
        List<Interval> awake = List.of(new Interval(t("08:00"), t("22:00"))); // 06:00 and 23:30 asleep
        List<LocalDateTime> c = Collapses.drawAtActivities(acts, awake, 200, 1);
        assertEquals(200, c.size());
        for (LocalDateTime x : c) {
            assertTrue(x.equals(t("09:00").plusSeconds(1)) || x.equals(t("12:30").plusSeconds(1)), x.toString());
        }
        long at9 = c.stream().filter(x -> x.getHour() == 9).count();
        assertTrue(at9 > 60 && at9 < 140, "drawn uniformly over the two activities: " + at9 + " of 200 at 09:00");
    }

    @Test
    void uniformAndMovingDiffer() {
        List<Interval> awake = List.of(new Interval(t("08:00"), t("22:00")));
        List<LocalDateTime> uniform = Collapses.draw(awake, 50, 1);
        assertTrue(uniform.stream().anyMatch(x -> !x.equals(t("09:00").plusSeconds(1))),
                "the uniform model draws moments, not activities");
        assertEquals(List.of(t("09:00").plusSeconds(1)),
                Collapses.drawAtActivities(List.of(t("09:00")), awake, 1, 7));
    }

    @Test
    void noAwakeActivityIsAClearError() {
        List<Interval> awake = List.of(new Interval(t("08:00"), t("22:00")));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Collapses.drawAtActivities(List.of(t("23:00")), awake, 5, 1));
        assertTrue(e.getMessage().contains("no recorded activity at home and awake"), e.getMessage());
    }
}

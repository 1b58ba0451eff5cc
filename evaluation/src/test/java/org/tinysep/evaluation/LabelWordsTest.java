package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.simulator.replay.Label;

/** Away and sleep labels are recognised by their words, whatever the recording calls them. */
class LabelWordsTest {

    private static final LocalDateTime T0 = LocalDateTime.parse("2020-01-01T00:00:00");

    @Test
    void awayAndSleepByTheirWords() {
        LabelWords w = LabelWords.defaults();
        for (String away : List.of("Leaving", "Leave_Home", "leave house", "Going Out", "Out", "Away", "Outside",
                "left the house", "not at home")) {
            assertEquals("Leaving", w.meaning(away), away);
        }
        for (String sleep : List.of("Sleeping", "Sleep", "go to bed", "Go_To_Bed", "Nap", "Bedtime", "in bed")) {
            assertEquals("Sleeping", w.meaning(sleep), sleep);
        }
        for (String awake : List.of("Bed_to_Toilet", "Toileting", "Spare_Time/TV", "Take_out_trash", "Work",
                "Relax", "Breakfast", "Wash_Dishes", "Enter_Home")) {
            assertEquals(awake, w.meaning(awake), awake);
        }
    }

    @Test
    void theDrawAndTheBlindTimeUseTheRecognisedLabels() {
        List<Label> recorded = List.of(new Label(T0, T0.plusHours(1), "Meal_Preparation", "R1"),
                new Label(T0.plusHours(1), T0.plusHours(3), "Leave_Home", "R1"),
                new Label(T0.plusHours(3), T0.plusHours(4), "Relax", "R1"),
                new Label(T0.plusHours(4), T0.plusHours(10), "Sleep", "R1"));
        List<Label> labels = LabelWords.defaults().normalise(recorded);
        assertEquals(List.of(new org.tinysep.simulator.replay.Interval(T0, T0.plusHours(1)),
                new org.tinysep.simulator.replay.Interval(T0.plusHours(3), T0.plusHours(4))),
                Collapses.candidates(labels, T0, T0.plusHours(10)), "never while out or asleep");
        String said = LabelWords.defaults().describe(recorded);
        assertTrue(said.startsWith("labels taken for away: Leave_Home (1); for asleep: Sleep (1); at home and awake:"
                + " Meal_Preparation (1), Relax (1)"), said);
        assertTrue(LabelWords.defaults().describe(List.of(recorded.get(0))).contains("warning: no label was taken"));
    }

    @Test
    void optionsReplaceThePatternsAndRejectABadOne() {
        EvalOptions o = EvalOptions.parse(new String[] {"--away-labels", "^Errand$", "--sleep-labels", "Rest"},
                Path.of("."));
        assertEquals("Leaving", o.words().meaning("Errand"));
        assertEquals("Leave_Home", o.words().meaning("Leave_Home"), "the default pattern is replaced");
        assertEquals("Sleeping", o.words().meaning("Rest"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> EvalOptions.parse(new String[] {"--sleep-labels", "(unclosed"}, Path.of(".")));
        assertTrue(e.getMessage().startsWith("--sleep-labels needs a regular expression"), e.getMessage());
    }
}

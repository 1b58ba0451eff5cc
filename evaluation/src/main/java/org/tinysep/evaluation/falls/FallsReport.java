package org.tinysep.evaluation.falls;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import org.tinysep.falldetection.internal.FallSettings;
import org.tinysep.simulator.person.RadioBudget;

/** Prints the figures of a falls run as Markdown tables. */
final class FallsReport {

    static final String CITATION = "SisFall: A. Sucerquia, J. D. López, J. F. Vargas-Bonilla, \"SisFall: A Fall and "
            + "Movement Dataset\", Sensors 2017, 17(1), 198, doi:10.3390/s17010198";

    private FallsReport() {
    }

    static String settings(FallSettings s) {
        return "impact ≥ " + s.impactMg() + " mg, posture change ≥ " + Math.round(s.postureChangeDeg())
                + "°, still SD ≤ " + s.stillSdMg() + " mg for " + s.stillFor().toSeconds() + " s within "
                + s.within().toSeconds() + " s" + (s.alreadyLyingDeg() < 180 ? ", not when already lying (≥ "
                + Math.round(s.alreadyLyingDeg()) + "° from the learned upright) before the impact" : "");
    }

    static void print(PrintStream out, Path folder, boolean loso, List<Scored> scored, List<String> settings,
            String how) {
        long falls = scored.stream().filter(Scored::fall).count();
        out.println("Fall detection on " + folder + ": " + scored.size() + " recordings (" + falls + " falls, "
                + (scored.size() - falls) + " ADLs). " + CITATION + ".");
        out.println("Node model: " + FallsCommand.nodeModel() + ".");
        out.println("How: " + how + ".");
        out.println("Impact instant: the recording's sample of largest magnitude (200 Hz); a fall counts as detected "
                + "when a FALL alert comes between it and 30 s after it; an ADL recording counts as correct without "
                + "any FALL alert.");
        out.println();
        out.println(loso ? "Settings chosen per fold (leave-one-subject-out: on the other subjects only):"
                : "Settings:");
        out.println("| held out | settings |");
        out.println("|---|---|");
        settings.forEach(out::println);
        out.println();
        Map<String, List<Scored>> bySubject = new TreeMap<>();
        Map<String, List<Scored>> byCode = new TreeMap<>();
        for (Scored s : scored) {
            bySubject.computeIfAbsent(s.stream().recording().subject(), k -> new ArrayList<>()).add(s);
            byCode.computeIfAbsent(s.stream().recording().code(), k -> new ArrayList<>()).add(s);
        }
        out.println("| subject | falls alerted | sensitivity | ADLs without alert | specificity | false alerts / ADL h "
                + "| delay p50 s | delay p95 s |");
        out.println("|---|---|---|---|---|---|---|---|");
        bySubject.forEach((subject, list) -> out.println(Figures.of(list).row(subject)));
        out.println(Figures.of(scored).row("**all**"));
        out.println();
        out.println("| code | recordings | with a FALL alert (falls: within 30 s of the impact) |");
        out.println("|---|---|---|");
        byCode.forEach((code, list) -> out.println("| " + code + " | " + list.size() + " | "
                + list.stream().filter(s -> s.fall() ? s.delay().isPresent() : !s.alerts().isEmpty()).count()
                + " |"));
        out.println();
        budget(out, scored);
    }

    private static void budget(PrintStream out, List<Scored> scored) {
        out.println("Radio budget (frames of " + RadioBudget.FRAME_HEADER_BYTES + " header bytes plus the payload: "
                + (RadioBudget.FRAME_HEADER_BYTES + RadioBudget.SUMMARY_BYTES) + " B a summary, "
                + RadioBudget.CHUNKS_PER_BURST + " frames and 1000 B a burst of 150 samples; docs/protocols/sunspot.md):");
        RadioBudget resting = new RadioBudget();
        for (int i = 0; i < 1800; i++) {
            resting.summary(); // an hour of lying still: no sample reaches the trigger, one summary every 2 s
        }
        resting.recorded(java.time.Duration.ofHours(1));
        out.println("- resting (still, no burst): " + resting.perHour());
        line(out, "walking (D01, D02)", scored, Set.of("D01", "D02"));
        line(out, "stairs (D05, D06)", scored, Set.of("D05", "D06"));
        line(out, "jogging (D03, D04)", scored, Set.of("D03", "D04"));
        line(out, "all ADL recordings", scored, null);
    }

    private static void line(PrintStream out, String what, List<Scored> scored, Set<String> codes) {
        RadioBudget sum = new RadioBudget();
        for (Scored s : scored) {
            String code = s.stream().recording().code();
            if (!s.fall() && (codes == null || codes.contains(code))) {
                sum.add(s.stream().budget());
            }
        }
        out.println("- " + what + ": " + sum.perHour() + " over " + String.format(java.util.Locale.ROOT, "%.2f",
                sum.hours()) + " h");
    }
}

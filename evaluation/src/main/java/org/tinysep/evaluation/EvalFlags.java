package org.tinysep.evaluation;

import java.nio.file.Path;
import java.util.List;
import org.tinysep.tools.cli.OptionTypes;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@link Evaluate}'s command line as picocli fills it (tools/org.tinysep.tools.cli); {@link #options} checks it. */
@Command(name = "./evaluate.sh", sortOptions = false,
        description = "Evaluates the inactivity alert of the real platform on a recorded home and prints the table, "
                + "detectors side by side (evaluation/README.md).",
        footer = {"", "Also: ./evaluate.sh falls --help (fall detection on SisFall), ./evaluate.sh --engine core --help "
                + "(the detector core without the platform)."})
final class EvalFlags {

    @Parameters(arity = "0..1", paramLabel = "A|B|<folder>", description = "Ordonez Home A / B (default A), converted "
            + "from data/ordonez in the repository (--ordonez DIR reads another copy), or a folder with events.csv "
            + "and labels.csv")
    String home = "A";
    @Option(names = "--collapses", paramLabel = "N", converter = OptionTypes.Count.class,
            description = "injected collapses per detector (default 200)")
    int collapses = 200;
    @Option(names = "--seed", paramLabel = "S", converter = OptionTypes.Seed.class,
            description = "seed of the collapse draw (default 1)")
    long seed = 1;
    @Option(names = "--warmup-hours", paramLabel = "H", converter = OptionTypes.AtLeastOne.class,
            description = "recorded hours replayed before each collapse (default 6)")
    int warmupHours = 6;
    @Option(names = "--parallel", paramLabel = "P", converter = OptionTypes.AtLeastOne.class,
            description = "platform processes at once (default 2)")
    int parallel = 2;
    @Option(names = "--batch", paramLabel = "B", converter = OptionTypes.AtLeastOne.class, description = "collapses "
            + "per platform process, one after another in virtual time (default 1: every collapse from its own copy "
            + "of the snapshot)")
    int batch = 1;
    @Option(names = "--days", paramLabel = "D", converter = OptionTypes.Count.class,
            description = "only the first D days of the recording (default 0: all)")
    int days;
    @Option(names = "--split", paramLabel = "half|cvK", description = "half (default: learn from the first half, test "
            + "the second) or cvK: K folds by days, every day tested once with the other days as history "
            + "(cv<days> = leave-one-day-out)")
    String split = "half";
    @Option(names = "--detectors", paramLabel = "LEARNED,THESIS", split = ",",
            description = "values of Inactivity Recognition's detector key, side by side (default LEARNED,THESIS)")
    List<String> detectors = List.of("LEARNED", "THESIS");
    @Option(names = "--away-labels", paramLabel = "REGEX", description = "which labelled activities mean away "
            + "(case-insensitive, found anywhere in the name; the default matches Leaving, Leave_Home, Out, Away, ...: "
            + "README, \"Labels\")")
    String away = LabelWords.AWAY;
    @Option(names = "--sleep-labels", paramLabel = "REGEX", description = "which labelled activities mean asleep "
            + "(the default matches Sleeping, Sleep, go to bed, Nap, ...)")
    String sleep = LabelWords.SLEEP;
    @Option(names = "--residents", paramLabel = "N", converter = OptionTypes.Count.class, description = "the people "
            + "living in the home, as an installer sets Inactivity Recognition's residents (default: a folder's file "
            + "'residents', else 0: recognised from the history)")
    Integer residents;
    @Option(names = "--no-readme", description = "print the table only (default: also into evaluation/README.md)")
    boolean noReadme;
    @Option(names = "--readme", paramLabel = "FILE", description = "the README to write the table into "
            + "(default evaluation/README.md)")
    Path readme;
    @Option(names = "--ordonez", paramLabel = "DIR", description = "folder of the Ordonez files (default data/ordonez)")
    Path ordonez;
    @Option(names = "--dist", paramLabel = "DIR",
            description = "the distribution (default runtime/org.tinysep.launcher/target/tinysep)")
    Path dist;
    @Option(names = "--work", paramLabel = "DIR",
            description = "folder for state folders and converted files (default evaluation/target/work)")
    Path work;

    /**
     * @param repo    the repository, which the default folders are in
     * @param command the command line as typed, for the report
     * @return the options, checked
     */
    EvalOptions options(Path repo, String command) {
        return new EvalOptions(home, collapses, seed, warmupHours, parallel, batch, days, List.copyOf(detectors),
                ordonez != null ? ordonez : repo.resolve("data/ordonez"),
                dist != null ? dist : repo.resolve("runtime/org.tinysep.launcher/target/tinysep"),
                work != null ? work : repo.resolve("evaluation/target/work"),
                noReadme ? null : readme != null ? readme : repo.resolve("evaluation/README.md"), command, split,
                new LabelWords(pattern("--away-labels", away), pattern("--sleep-labels", sleep)), residents);
    }

    private static String pattern(String option, String v) {
        try {
            java.util.regex.Pattern.compile(v);
            return v;
        } catch (java.util.regex.PatternSyntaxException e) {
            throw new IllegalArgumentException(option + " needs a regular expression: " + e.getDescription()
                    + " in '" + v + "'");
        }
    }
}

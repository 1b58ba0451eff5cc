package org.tinysep.evaluation;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.tools.cli.OptionTypes;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.TypeConversionException;

/** {@link CoreSweep}'s command line as picocli fills it (tools/org.tinysep.tools.cli). */
@Command(name = "./evaluate.sh --engine core", sortOptions = false, description = "The detector core without the "
        + "platform (CoreSweep, seconds per home): every false alarm and missed collapse, then one table for all "
        + "homes (evaluation/README.md). The old form HOME [half|cv K] [N] still works.")
final class CoreSweepFlags {

    @Option(names = "--engine", paramLabel = "core", hidden = true, description = "evaluate.sh's choice of this tool")
    String engine;
    @Option(names = "--model", paramLabel = "uniform|moving|both", converter = Models.class,
            description = "where the collapses are drawn (default uniform)")
    List<Collapses.Model> models = List.of(Collapses.Model.UNIFORM);
    @Option(names = "--split", paramLabel = "half|cvK",
            description = "half (default) or cvK: K folds by days")
    String split = "half";
    @Option(names = "--collapses", paramLabel = "N", converter = OptionTypes.Count.class,
            description = "collapses per home, model and detector (default 200)")
    int collapses = 200;
    @Option(names = "--residents", paramLabel = "N", converter = OptionTypes.Count.class, description = "the people "
            + "living in every home given, as an installer sets Inactivity Recognition's residents (default: a "
            + "folder's file 'residents', else 0: recognised from the history)")
    Integer residents;
    @Option(names = "--readme", description = "write the table between the results:core markers of README.md and "
            + "evaluation/README.md (default: print only; a sweep with -Dfloor=... must not overwrite them)")
    boolean readme;
    @Option(names = "--no-readme", description = "print only (the default)")
    boolean noReadme;
    @Parameters(paramLabel = "HOME", description = "A, B, a folder, or a derived home A:nomotion, B:two (default A B)")
    List<String> words = new ArrayList<>();

    /** The homes, the folds (0: half) and the collapses, the old positional form read too. */
    record Plan(List<String> homes, int folds, int collapses) {
    }

    Plan plan() {
        int k = folds(split);
        int n = collapses;
        List<String> homes = new ArrayList<>();
        for (int i = 0; i < words.size(); i++) {
            String w = words.get(i);
            if (w.equals("half")) {
                k = 0;
            } else if (w.equals("cv")) {
                if (i + 1 >= words.size()) {
                    throw new IllegalArgumentException("cv needs a number of folds, e.g. cv 4");
                }
                k = whole("cv", words.get(++i));
            } else if (w.matches("\\d+") && !homes.isEmpty()) {
                n = whole("the number of collapses", w);
            } else {
                homes.add(w);
            }
        }
        return new Plan(homes.isEmpty() ? List.of("A", "B") : homes, k, n);
    }

    boolean writeReadme() {
        return readme && !noReadme;
    }

    private static int folds(String split) {
        if (split.equals("half")) {
            return 0;
        }
        if (split.startsWith("cv")) {
            return whole("--split cvK", split.substring(2));
        }
        throw new IllegalArgumentException("--split needs half or cvK (e.g. cv4), not '" + split + "'");
    }

    private static int whole(String what, String v) {
        try {
            return Integer.parseInt(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + " needs a whole number, not '" + v + "'");
        }
    }

    /** uniform, moving or both. */
    static final class Models implements ITypeConverter<List<Collapses.Model>> {
        @Override
        public List<Collapses.Model> convert(String v) {
            return switch (v) {
            case "uniform" -> List.of(Collapses.Model.UNIFORM);
            case "moving" -> List.of(Collapses.Model.MOVING);
            case "both" -> List.of(Collapses.Model.UNIFORM, Collapses.Model.MOVING);
            default -> throw new TypeConversionException("needs uniform, moving or both, not '" + v + "'");
            };
        }
    }
}

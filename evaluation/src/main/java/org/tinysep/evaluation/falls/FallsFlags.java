package org.tinysep.evaluation.falls;

import java.nio.file.Path;
import org.tinysep.tools.cli.OptionTypes;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code ./evaluate.sh falls}'s command line as picocli fills it (tools/org.tinysep.tools.cli). */
@Command(name = "./evaluate.sh falls", sortOptions = false, description = "Plays every SisFall recording of the folder "
        + "through the person node's rule into Fall Detection and prints the figures (docs/fall-detection.md).")
public final class FallsFlags {

    @Parameters(arity = "0..1", paramLabel = "folder", description = "laid out like SisFall: "
            + "<subject>/<code>_<subject>_<trial>.txt[.gz] (default: $TINYSEP_SISFALL, else data/sisfall in the "
            + "repository)")
    Path folder;
    @Option(names = "--loso", description = "leave-one-subject-out: each subject judged with settings chosen on the "
            + "others only (default: Fall Detection's default settings on every recording)")
    boolean loso;
    @Option(names = "--why", description = "list every missed fall and every false alert with the setting that "
            + "decided it")
    boolean why;
    @Option(names = "--in-process", description = "judge with Fall Detection's detector class in this process "
            + "(seconds; settings are always chosen this way) instead of through the real distribution (the default: "
            + "one platform process per subject, the recordings played over UDP in lock-step, the alerts read back "
            + "from its event log; needs runtime/org.tinysep.launcher/target/tinysep, which ./evaluate.sh builds)")
    boolean inProcess;
    @Option(names = "--parallel", paramLabel = "P", converter = OptionTypes.AtLeastOne.class,
            description = "platform processes at once (default 2)")
    int parallel = 2;
    @Option(names = "--dist", paramLabel = "DIR",
            description = "the distribution (default runtime/org.tinysep.launcher/target/tinysep)")
    Path dist;
    @Option(names = "--work", paramLabel = "DIR", description = "where the platforms' home and state folders go "
            + "(default evaluation/target/falls-platforms)")
    Path work;
    @Option(names = {"-h", "--help"}, usageHelp = true, description = "print this text")
    boolean help;
}

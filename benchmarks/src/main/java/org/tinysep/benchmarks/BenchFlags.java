package org.tinysep.benchmarks;

import java.nio.file.Path;
import java.util.List;
import org.tinysep.tools.cli.OptionTypes;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** The benchmarks' command line as picocli fills it (tools/org.tinysep.tools.cli); a flag's last value counts. */
@Command(name = "./benchmarks/run.sh", sortOptions = false, description = "Runs every benchmark against the real "
        + "distribution (tinysep.jar as its own process) and writes RESULTS.md and the plots (benchmarks/README.md). "
        + "run.sh passes --dist, --out and --images first: given again, the later value counts.")
final class BenchFlags {

    @Option(names = "--smoke", description = "a few seconds each (what CI runs); figures not meaningful")
    boolean smoke;
    @Option(names = "--only", paramLabel = "SECTION,...", split = ",", description = "run only the sections whose "
            + "names start so, e.g. footprint,scale (while working on one; default all)")
    List<String> only = List.of();
    @Option(names = "--repeat", paramLabel = "N", converter = OptionTypes.AtLeastOne.class, description = "runs of "
            + "the thesis, throughput and latency steps (default 3, with --smoke 1)")
    Integer repeat;
    @Option(names = "--append", description = "add the sections to the --out file's earlier run instead of "
            + "rewriting it (with --only)")
    boolean append;
    @Option(names = "--dist", paramLabel = "DIR",
            description = "the distribution (default runtime/org.tinysep.launcher/target/tinysep)")
    Path dist = Path.of("runtime/org.tinysep.launcher/target/tinysep");
    @Option(names = "--out", paramLabel = "FILE", description = "the results (default benchmarks/RESULTS.md)")
    Path out = Path.of("benchmarks/RESULTS.md");
    @Option(names = "--images", paramLabel = "DIR", description = "the plots (default docs/images)")
    Path images = Path.of("docs/images");

    /** @return the runs of the repeated steps */
    int repeat() {
        return repeat != null ? repeat : smoke ? 1 : 3;
    }
}

package org.tinysep.evaluation.falls;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.tinysep.falldetection.internal.FallSettings;
import org.tinysep.simulator.person.NodeResampler;
import org.tinysep.simulator.person.PersonNodeRule;
import org.tinysep.simulator.person.SisfallRecording;

/**
 * {@code ./evaluate.sh falls [folder] [--loso] [--why]}: plays every SisFall recording of the folder through the
 * person node's rule into Fall Detection's detector and prints the figures (docs/fall-detection.md).
 */
public final class FallsCommand {

    static final String USAGE = """
            usage: ./evaluate.sh falls [folder] [--loso] [--why]
              folder   laid out like SisFall: <subject>/<code>_<subject>_<trial>.txt[.gz]
                       (default: $TINYSEP_SISFALL, else data/sisfall in the repository)
              --loso   leave-one-subject-out: each subject judged with settings chosen on the others only
                       (default: Fall Detection's default settings on every recording)
              --why    list every missed fall and every false alert with the setting that decided it
            """;

    private FallsCommand() {
    }

    /** @return the process's exit code */
    public static int main(String[] args, Path repo, PrintStream out) throws IOException {
        Path folder = null;
        boolean loso = false;
        boolean why = false;
        for (String a : args) {
            switch (a) {
                case "--loso" -> loso = true;
                case "--why" -> why = true;
                case "-h", "--help" -> {
                    out.print(USAGE);
                    return 0;
                }
                default -> {
                    if (a.startsWith("-") || folder != null) {
                        throw new IllegalArgumentException("falls: unknown argument '" + a + "'\n" + USAGE);
                    }
                    folder = Path.of(a);
                }
            }
        }
        if (folder == null) {
            String env = System.getenv("TINYSEP_SISFALL");
            folder = env != null && !env.isBlank() ? Path.of(env) : repo.resolve("data/sisfall");
        }
        if (!Files.isDirectory(folder)) {
            throw new IllegalArgumentException("falls: " + folder + " is not a folder; give a folder laid out like "
                    + "SisFall (<subject>/<code>_<subject>_<trial>.txt.gz) or set TINYSEP_SISFALL\n" + USAGE);
        }
        Map<String, List<NodeStream>> bySubject = load(folder);
        if (bySubject.isEmpty()) {
            throw new IllegalArgumentException("falls: no SisFall recordings (<code>_<subject>_<trial>.txt[.gz]) in "
                    + folder);
        }
        List<Scored> scored = new ArrayList<>();
        List<String> settingsLines = new ArrayList<>();
        if (loso) {
            for (Loso.Fold f : Loso.run(bySubject)) {
                scored.addAll(f.scored());
                settingsLines.add("| " + f.subject() + " | " + FallsReport.settings(f.chosen()) + " |");
            }
        } else {
            for (List<NodeStream> streams : bySubject.values()) {
                scored.addAll(streams.parallelStream().map(s -> Scored.run(s, FallSettings.DEFAULT)).toList());
            }
            settingsLines.add("| all | " + FallsReport.settings(FallSettings.DEFAULT) + " (the defaults) |");
        }
        FallsReport.print(out, folder, loso, scored, settingsLines);
        if (why) {
            Why.print(out, scored);
        }
        out.println(Figures.of(scored).lastLine());
        return 0;
    }

    static Map<String, List<NodeStream>> load(Path folder) throws IOException {
        List<Path> files;
        try (Stream<Path> walk = Files.walk(folder)) {
            files = walk.filter(Files::isRegularFile).filter(SisfallRecording::isRecording).sorted().toList();
        }
        List<NodeStream> streams = files.parallelStream().map(f -> {
            try {
                return NodeStream.of(SisfallRecording.read(f));
            } catch (IOException e) {
                throw new UncheckedIOException(f + ": " + e.getMessage(), e);
            }
        }).toList();
        Map<String, List<NodeStream>> by = new TreeMap<>();
        for (NodeStream s : streams) {
            by.computeIfAbsent(s.recording().subject(), k -> new ArrayList<>()).add(s);
        }
        return by;
    }

    /** @return how the node is modelled, for the report */
    static String nodeModel() {
        return "SisFall's ADXL345 (200 Hz, ±16 g) clipped per axis to ±" + NodeResampler.RANGE_MG / 1000
                + " g (the Sun SPOT's LIS3L02AQ at its ±6 g range) and averaged in fours to the node's "
                + NodeResampler.NODE_RATE_HZ + " Hz; the node's rule: a summary every 2 s, a burst of 150 samples "
                + "(1 s before, 2 s after) when the magnitude reaches " + PersonNodeRule.TRIGGER_MG + " mg; "
                + NodeStream.REST_SECONDS + " s of rest (the recording's last second's mean, repeated) padded after "
                + "each recording, so a fall near its end can be confirmed; the padding is not counted in ADL hours";
    }
}

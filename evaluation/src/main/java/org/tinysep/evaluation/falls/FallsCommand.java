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
import org.tinysep.tools.cli.Cli;

/**
 * {@code ./evaluate.sh falls [folder] [--loso] [--why]}: plays every SisFall recording of the folder through the
 * person node's rule into Fall Detection's detector and prints the figures (docs/fall-detection.md).
 */
public final class FallsCommand {

    private FallsCommand() {
    }

    /**
     * @param args the command line ({@link FallsFlags})
     * @return the process's exit code (0; {@code --help} prints the usage on {@code out})
     * @throws IllegalArgumentException naming a refused option or argument, a folder that is not there or holds no
     *                                  recordings
     */
    public static int main(String[] args, Path repo, PrintStream out) throws Exception {
        FallsFlags flags = Cli.parse(new FallsFlags(), args);
        if (flags.help) {
            out.print(Cli.usage(flags));
            return 0;
        }
        boolean loso = flags.loso;
        boolean why = flags.why;
        boolean inProcess = flags.inProcess;
        int parallel = flags.parallel;
        Path dist = flags.dist != null ? flags.dist : repo.resolve("runtime/org.tinysep.launcher/target/tinysep");
        Path work = flags.work != null ? flags.work : repo.resolve("evaluation/target/falls-platforms");
        Path folder = flags.folder;
        if (folder == null) {
            String env = System.getenv("TINYSEP_SISFALL");
            folder = env != null && !env.isBlank() ? Path.of(env) : repo.resolve("data/sisfall");
        }
        if (!Files.isDirectory(folder)) {
            throw new IllegalArgumentException("falls: " + folder + " is not a folder; give a folder laid out like "
                    + "SisFall (<subject>/<code>_<subject>_<trial>.txt.gz) or set TINYSEP_SISFALL");
        }
        Map<String, List<NodeStream>> bySubject = load(folder);
        if (bySubject.isEmpty()) {
            throw new IllegalArgumentException("falls: no SisFall recordings (<code>_<subject>_<trial>.txt[.gz]) in "
                    + folder);
        }
        List<Scored> scored = new ArrayList<>();
        List<String> settingsLines = new ArrayList<>();
        Map<String, FallSettings> chosen = new TreeMap<>();
        if (loso) {
            for (Loso.Fold f : Loso.run(bySubject)) {
                scored.addAll(f.scored());
                chosen.put(f.subject(), f.chosen());
                settingsLines.add("| " + f.subject() + " | " + FallsReport.settings(f.chosen()) + " |");
            }
        } else {
            for (List<NodeStream> streams : bySubject.values()) {
                scored.addAll(Scored.runSubject(streams, FallSettings.DEFAULT));
            }
            bySubject.keySet().forEach(subject -> chosen.put(subject, FallSettings.DEFAULT));
            settingsLines.add("| all | " + FallsReport.settings(FallSettings.DEFAULT) + " (the defaults) |");
        }
        String how = "judged in process (Fall Detection's detector class fed by the node's rule)";
        if (!inProcess) {
            long wall = System.nanoTime();
            scored = ThroughPlatform.run(dist, work, bySubject, chosen::get, parallel, scored);
            how = String.format(java.util.Locale.ROOT, "judged through the real distribution: one platform per "
                    + "subject (%d at once), the recordings played as the person node's frames over UDP in lock-step "
                    + "(%d s apart), the FALL alerts read back from the platform's event log; %d s wall time", parallel,
                    org.tinysep.evaluation.FallPlatforms.gapSeconds(), (System.nanoTime() - wall) / 1_000_000_000L);
        }
        FallsReport.print(out, folder, loso, scored, settingsLines, how);
        if (why) {
            Why.print(out, scored, chosen::get);
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

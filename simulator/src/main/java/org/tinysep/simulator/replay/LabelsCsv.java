package org.tinysep.simulator.replay;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The optional label file {@code labels.csv} (simulator/README-replay.md): header {@value #HEADER}; times local ISO-8601 without
 * zone; resident may be empty. Used for evaluation only. Labels are kept as recorded (an end before the start is
 * not rejected, see {@link Label#isProper()}).
 */
public final class LabelsCsv {

    /** The exact header line. */
    public static final String HEADER = "start_iso,end_iso,activity,resident";

    private LabelsCsv() {
    }

    /**
     * @param file labels.csv (UTF-8; CRLF or LF; blank lines skipped)
     * @return the labels in file order
     * @throws IOException if the file cannot be read
     * @throws ReplayFormatException naming file and line for a wrong header or a malformed row
     */
    public static List<Label> read(Path file) throws IOException, ReplayFormatException {
        return parse(Files.readAllLines(file, StandardCharsets.UTF_8), file.getFileName().toString());
    }

    static List<Label> parse(List<String> lines, String name) throws ReplayFormatException {
        List<Label> labels = new ArrayList<>();
        Csv.rows(lines, HEADER, name, (f, line) -> {
            if (f[2].isEmpty()) {
                throw new ReplayFormatException(name, line, "activity is empty");
            }
            labels.add(new Label(Csv.time(f[0], name, line), Csv.time(f[1], name, line), f[2], f[3]));
        });
        return labels;
    }

    /**
     * @param labels labels to write in the given order
     * @param file   target file, replaced (LF line ends)
     * @throws IOException if writing fails
     * @throws IllegalArgumentException if a name cannot be written unquoted
     */
    public static void write(List<Label> labels, Path file) throws IOException {
        try (BufferedWriter w = Csv.writer(file, HEADER)) {
            for (Label l : labels) {
                w.write(Csv.format(l.start()) + "," + Csv.format(l.end()) + ","
                        + Csv.check(l.activity(), "activity") + ","
                        + Csv.check(l.resident(), "resident") + "\n");
            }
        }
    }
}

package org.tinysep.evaluation.falls;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.simulator.person.SyntheticRecordings;

/**
 * The smoke run of {@code ./evaluate.sh falls}: synthetic recordings in SisFall's layout (SisFall itself is not in
 * the repository), two subjects, leave-one-subject-out; checks the report's structure, not tuned figures.
 */
class FallsCommandTest {

    @TempDir
    Path dir;

    private String run(String... args) throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8)) {
            assertEquals(0, FallsCommand.main(args, dir, out));
        }
        return bytes.toString(StandardCharsets.UTF_8);
    }

    @Test
    void looReportHasEverySubjectEveryCodeTheBudgetAndTheLastLine() throws Exception {
        SyntheticRecordings.write(dir.resolve("set"), "SX01", 1);
        SyntheticRecordings.write(dir.resolve("set"), "SX02", 2);
        String out = run(dir.resolve("set").toString(), "--loso", "--why", "--in-process");
        List<String> lines = out.lines().toList();
        assertTrue(lines.get(0).contains("10 recordings (4 falls, 6 ADLs)"), lines.get(0));
        assertTrue(out.contains("| SX01 | impact ≥ "), out);
        assertTrue(out.contains("| SX02 | impact ≥ "), out);
        for (String code : SyntheticRecordings.CODES) {
            assertTrue(out.contains("| " + code + " | 2 | "), code + " in\n" + out);
        }
        assertTrue(out.lines().anyMatch(l -> l.matches("\\| \\*\\*all\\*\\* \\| \\d/4 \\| .*")), out);
        assertTrue(out.contains("- resting (still, no burst): 1800 frames/h, 46.8 kB/h"), out);
        assertTrue(out.contains("Why (relative to the settings each recording was judged with):"), out);
        String last = lines.get(lines.size() - 1);
        assertTrue(last.matches("falls: sensitivity [0-9.]+ %, specificity [0-9.]+ %, false alerts per ADL hour "
                + "[0-9.]+, delay p50 ([0-9.]+|n/a) s, p95 ([0-9.]+|n/a) s"), last);
    }

    @Test
    void aFolderThatIsNotThereIsSaidInWords() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> run(dir.resolve("nowhere").toString()));
        assertTrue(e.getMessage().contains("is not a folder"), e.getMessage());
        IllegalArgumentException empty = assertThrows(IllegalArgumentException.class, () -> run(dir.toString()));
        assertTrue(empty.getMessage().contains("no SisFall recordings"), empty.getMessage());
        assertThrows(IllegalArgumentException.class, () -> run("--fast"));
    }
}

package org.tinysep.evaluation.falls;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.simulator.person.SyntheticRecordings;
import org.tinysep.testsupport.repo.RepoFiles;

/**
 * CI smoke run of {@code ./evaluate.sh falls} through the real distribution (issue 26, item 5): two synthetic
 * subjects in SisFall's layout, leave-one-subject-out, one platform per subject. Asserts the report's structure and
 * that the platform's alerts were read back for every recording, not tuned figures.
 */
class FallsSmokeIT {

    @TempDir
    Path dir;

    @Test
    void twoSyntheticSubjectsThroughThePlatform() throws Exception {
        SyntheticRecordings.write(dir.resolve("set"), "SX01", 11);
        SyntheticRecordings.write(dir.resolve("set"), "SX02", 12);
        Path repo = RepoFiles.root();
        String dist = System.getProperty("tinysep.dist", repo.resolve("runtime/org.tinysep.launcher/target/tinysep")
                .toString());
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8)) {
            assertEquals(0, FallsCommand.main(new String[] {dir.resolve("set").toString(), "--loso", "--dist", dist,
                "--work", dir.resolve("work").toString()}, repo, out));
        }
        String report = bytes.toString(StandardCharsets.UTF_8);
        List<String> lines = report.lines().toList();
        assertTrue(report.contains("How: judged through the real distribution"), report);
        assertTrue(report.contains("| SX01 | ") && report.contains("| SX02 | "), report);
        assertTrue(lines.get(lines.size() - 1).startsWith("falls: sensitivity "), report);
        assertTrue(report.lines().anyMatch(l -> l.matches("\\| \\*\\*all\\*\\* \\| [1-4]/4 \\| .*")),
                "the platform's FALL alerts were read back (a synthetic fall is an obvious one): " + report);
    }
}

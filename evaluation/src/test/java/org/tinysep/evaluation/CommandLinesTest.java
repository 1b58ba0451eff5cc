package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.tinysep.testsupport.repo.RepoFiles;

/**
 * The three command lines of {@code ./evaluate.sh} (the platform evaluation, {@code falls}, {@code --engine core}) as
 * a user types them, each in its own JVM: an unknown flag is one line naming it, the usage and exit code 2, before
 * anything runs; {@code --help} prints the usage with exit code 0.
 */
class CommandLinesTest {

    record Ran(int code, String out, String err) {
        String firstErrorLine() {
            return err.lines().findFirst().orElse("");
        }
    }

    private static Ran java(String main, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Dtinysep.repo=" + RepoFiles.root(), "-cp", System.getProperty("java.class.path"), main));
        command.addAll(List.of(args));
        Path err = Files.createTempFile("evaluate-", ".err");
        try {
            Process p = new ProcessBuilder(command).redirectError(err.toFile()).start();
            p.getOutputStream().close();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the command ends");
            return new Ran(p.exitValue(), out, Files.readString(err));
        } finally {
            Files.deleteIfExists(err);
        }
    }

    @Test
    void theEvaluationRefusesAnUnknownFlag() throws Exception {
        Ran r = java(Evaluate.class.getName(), "A", "--colapses", "20");
        assertEquals(2, r.code(), r.err());
        assertEquals("error: Unknown options: '--colapses', '20'", r.firstErrorLine());
        assertTrue(r.err().contains("--warmup-hours") && r.err().contains("--no-readme"), "the usage: " + r.err());
        Ran help = java(Evaluate.class.getName(), "--help");
        assertEquals(0, help.code(), help.err());
        assertTrue(help.out().contains("--away-labels") && help.out().contains("(default 200)"), help.out());
    }

    @Test
    void fallsRefusesAnUnknownFlag() throws Exception {
        Ran r = java(Evaluate.class.getName(), "falls", "--fast");
        assertEquals(2, r.code(), r.err());
        assertEquals("error: Unknown option: '--fast'", r.firstErrorLine());
        assertTrue(r.err().contains("--in-process"), "the falls usage: " + r.err());
        Ran bad = java(Evaluate.class.getName(), "falls", "--parallel", "two");
        assertEquals(2, bad.code(), bad.err());
        assertEquals("error: Invalid value for option '--parallel': needs a whole number >= 1, not 'two'",
                bad.firstErrorLine());
        Ran help = java(Evaluate.class.getName(), "falls", "--help");
        assertEquals(0, help.code(), help.err());
        assertTrue(help.out().contains("--loso") && help.out().contains("TINYSEP_SISFALL"), help.out());
    }

    @Test
    void theCoreSweepRefusesAnUnknownFlag() throws Exception {
        Ran r = java(CoreSweep.class.getName(), "--engine", "core", "--modle", "both", "A");
        assertEquals(2, r.code(), r.err());
        assertEquals("error: Unknown option: '--modle'", r.firstErrorLine()); // 'both' is taken for a home
        Ran bad = java(CoreSweep.class.getName(), "--engine", "core", "--model", "sideways", "A");
        assertEquals(2, bad.code(), bad.err());
        assertTrue(bad.firstErrorLine().startsWith("error: Invalid value for option '--model'")
                && bad.firstErrorLine().endsWith("needs uniform, moving or both, not 'sideways'"), bad.err());
    }

    @Test
    void optionsParsedInProcessKeepTheirDefaultsAndOldForms() {
        Path repo = RepoFiles.root();
        EvalOptions d = EvalOptions.parse(new String[0], repo);
        assertEquals("A", d.home());
        assertEquals(200, d.collapses());
        assertEquals(6, d.warmupHours());
        assertEquals(List.of("LEARNED", "THESIS"), d.detectors());
        assertEquals(repo.resolve("evaluation/README.md"), d.readme());
        EvalOptions o = EvalOptions.parse(new String[] {"B", "--detectors", "THESIS", "--no-readme", "--split", "cv4",
            "--parallel", "3"}, repo);
        assertEquals(List.of("THESIS"), o.detectors());
        assertEquals(null, o.readme());
        assertEquals("cv4", o.split());
        assertEquals(3, o.parallel());
        assertTrue(o.command().startsWith("./evaluate.sh B --detectors THESIS"), o.command());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> EvalOptions.parse(new String[] {"A", "--batch", "0"}, repo));
        assertEquals("Invalid value for option '--batch': needs a whole number >= 1, not '0'", e.getMessage());
        CoreSweepFlags.Plan old = org.tinysep.tools.cli.Cli.parse(new CoreSweepFlags(), "B", "cv", "4", "50").plan();
        assertEquals(new CoreSweepFlags.Plan(List.of("B"), 4, 50), old);
        CoreSweepFlags.Plan now = org.tinysep.tools.cli.Cli.parse(new CoreSweepFlags(), "--split", "cv3", "A:nomotion")
                .plan();
        assertEquals(new CoreSweepFlags.Plan(List.of("A:nomotion"), 3, 200), now);
        assertEquals(List.of("A", "B"), org.tinysep.tools.cli.Cli.parse(new CoreSweepFlags()).plan().homes());
    }
}

package org.tinysep.benchmarks;

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
import org.tinysep.tools.cli.Cli;

/**
 * {@code ./benchmarks/run.sh}'s command line: a mistyped flag (which the benchmarks used to ignore, running the full
 * 30-minute run instead of the smoke run) is refused before anything starts.
 */
class CommandLineTest {

    @Test
    void aMistypedFlagIsRefusedWithExitCode2BeforeAnyBenchmarkRuns() throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "--dist", "nowhere", "--smoek"));
        Path err = Files.createTempFile("benchmarks-", ".err");
        try {
            Process p = new ProcessBuilder(command).redirectError(err.toFile()).start();
            p.getOutputStream().close();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the benchmarks end at once");
            String said = Files.readString(err);
            assertEquals(2, p.exitValue(), said);
            assertEquals("error: Unknown option: '--smoek'", said.lines().findFirst().orElse(""));
            assertTrue(said.contains("--repeat") && said.contains("--only"), "the usage follows: " + said);
            assertTrue(!out.contains("benchmarks: footprint"), "no benchmark ran: " + out);
        } finally {
            Files.deleteIfExists(err);
        }
    }

    @Test
    void defaultsAndTheUsersValueAfterRunShs() {
        BenchFlags d = Cli.parse(new BenchFlags());
        assertEquals(3, d.repeat());
        assertEquals(Path.of("benchmarks/RESULTS.md"), d.out);
        assertEquals(List.of(), d.only);
        BenchFlags smoke = Cli.parse(new BenchFlags(), "--dist", "dist", "--out", "benchmarks/RESULTS.md", "--smoke",
                "--only", "footprint,scale", "--out", "/tmp/r.md");
        assertEquals(1, smoke.repeat());
        assertEquals(Path.of("/tmp/r.md"), smoke.out, "run.sh's defaults come first, the user's win");
        assertEquals(List.of("footprint", "scale"), smoke.only);
        assertEquals(5, Cli.parse(new BenchFlags(), "--smoke", "--repeat", "5").repeat());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Cli.parse(new BenchFlags(), "--repeat", "0"));
        assertEquals("Invalid value for option '--repeat': needs a whole number >= 1, not '0'", e.getMessage());
    }
}

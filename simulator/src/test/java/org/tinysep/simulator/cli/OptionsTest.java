package org.tinysep.simulator.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

class OptionsTest {

    @Test
    void defaultsAndValues() {
        Options d = Options.parse(new String[0]);
        assertEquals("flat-a", d.flat());
        assertEquals(47011, d.amicaPort());
        assertEquals(47020, d.syncPort());
        assertFalse(d.lockstep());
        assertEquals(86400, d.untilSecond());
        Options o = Options.parse(new String[] {"--lockstep", "--from", "7:30", "--until", "18:00", "--seed", "42",
                "--target", "10.0.0.5", "--sunspot-port", "5000"});
        assertTrue(o.lockstep());
        assertEquals(7 * 3600 + 1800, o.fromSecond());
        assertEquals(42, o.seed());
        assertEquals("10.0.0.5", o.target());
        assertEquals(5000, o.sunSpotPort());
        assertEquals(5, d.paceMillis());
        assertEquals(0.002, d.wander());
        assertTrue(d.fullRate());
        assertFalse(Options.parse(new String[] {"--rate", "changes", "--no-pendant"}).fullRate());
        assertTrue(Options.parse(new String[] {"--no-pendant"}).noPendant());
        assertEquals(47013, Options.parse(new String[] {"--amica-port", "47012", "--amica-port", "47013"}).amicaPort(),
                "the last value of a repeated option counts, as before");
    }

    /** The runnable jar's entry point: an unknown flag is one line naming it, the usage and exit code 2. */
    @Test
    void theCommandRefusesAnUnknownFlagWithExitCode2AndPrintsItsHelp() throws Exception {
        Ran refused = java("--lockstep", "--colour", "red");
        assertEquals(2, refused.code(), refused.err());
        assertEquals("error: Unknown options: '--colour', 'red'", refused.err().lines().findFirst().orElseThrow());
        assertTrue(refused.err().contains("--no-pendant"), "the usage follows: " + refused.err());
        Ran help = java("--help");
        assertEquals(0, help.code(), help.err());
        assertTrue(help.out().contains("--wait-platform") && help.out().contains("(default 47011)"), help.out());
    }

    record Ran(int code, String out, String err) {
    }

    private static Ran java(String... args) throws Exception {
        java.util.List<String> command = new java.util.ArrayList<>(java.util.List.of(
                java.nio.file.Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), Main.class.getName()));
        command.addAll(java.util.List.of(args));
        java.nio.file.Path err = java.nio.file.Files.createTempFile("simulator-", ".err");
        try {
            Process p = new ProcessBuilder(command).redirectError(err.toFile()).start();
            p.getOutputStream().close();
            String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            assertTrue(p.waitFor(60, java.util.concurrent.TimeUnit.SECONDS), "the simulator ends");
            return new Ran(p.exitValue(), out, java.nio.file.Files.readString(err));
        } finally {
            java.nio.file.Files.deleteIfExists(err);
        }
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
            "--seed abc; option '--seed': needs a whole number >= 0, not 'abc'",
            "--from 25:00; option '--from': needs HH:MM",
            "--amica-port 70000; option '--amica-port': needs a port 1..65535, not '70000'",
            "--speed 0; --speed must be > 0",
            "--wander -1; option '--wander': needs a number >= 0",
            "--date 23.11.2026; option '--date': needs yyyy-mm-dd",
            "--rate some; option '--rate': needs full or changes",
            "--colour red; Unknown options: '--colour', 'red'",
            "--lockstep --colour; Unknown option: '--colour'",
            "--from 10:00 --until 09:00; --until must be after --from",
            "--target; Missing required parameter for option '--target'",
            "stray; Unmatched argument at index 0: 'stray'"})
    void badOptionsAreNamed(String args, String expected) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Options.parse(args.split(" ")));
        assertTrue(e.getMessage().contains(expected), e.getMessage());
    }
}

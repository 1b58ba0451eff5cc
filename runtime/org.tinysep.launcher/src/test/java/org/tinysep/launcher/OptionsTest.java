package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class OptionsTest {

    private static final Path HOME = Path.of("/opt/tinysep");

    @Test
    void defaultsToInteractiveInTheDefaultHome() {
        Options o = Options.parse(List.of(), Map.of(), HOME);
        assertFalse(o.daemon());
        assertFalse(o.help());
        assertEquals(HOME, o.home());
    }

    @Test
    void daemonFromFlagOrEnvironment() {
        assertTrue(Options.parse(List.of("--daemon"), Map.of(), HOME).daemon());
        assertTrue(Options.parse(List.of("-d"), Map.of(), HOME).daemon());
        assertTrue(Options.parse(List.of(), Map.of("TINYSEP_DAEMON", "1"), HOME).daemon());
        assertTrue(Options.parse(List.of(), Map.of("TINYSEP_DAEMON", " TRUE "), HOME).daemon());
        assertFalse(Options.parse(List.of(), Map.of("TINYSEP_DAEMON", "0"), HOME).daemon());
    }

    @Test
    void headlessFromFlagOrEnvironment() {
        assertFalse(Options.parse(List.of(), Map.of(), HOME).headless(), "the web console is there by default");
        assertTrue(Options.parse(List.of("--headless"), Map.of(), HOME).headless());
        assertTrue(Options.parse(List.of(), Map.of("TINYSEP_HEADLESS", "yes"), HOME).headless());
        assertFalse(Options.parse(List.of(), Map.of("TINYSEP_HEADLESS", "0"), HOME).headless());
        assertTrue(Options.USAGE.contains("--headless"), Options.USAGE);
    }

    @Test
    void homeInBothSpellingsIsMadeAbsolute() {
        assertEquals(Path.of("/srv/t"), Options.parse(List.of("--home", "/srv/t"), Map.of(), HOME).home());
        assertEquals(Path.of("/srv/u"), Options.parse(List.of("--home=/srv/x/../u"), Map.of(), HOME).home());
        assertTrue(Options.parse(List.of("--home", "rel"), Map.of(), HOME).home().isAbsolute());
    }

    @Test
    void stateFolderDefaultsToHomeVarAndFollowsVar() {
        assertEquals(Path.of("/srv/t/var"), Options.parse(List.of("--home", "/srv/t"), Map.of(), HOME).var());
        assertEquals(Path.of("/data/state"), Options.parse(List.of("--var", "/data/state"), Map.of(), HOME).var());
        assertEquals(Path.of("/data/s2"), Options.parse(List.of("--var=/data/x/../s2"), Map.of(), HOME).var());
        assertTrue(Options.parse(List.of("--var", "rel"), Map.of(), HOME).var().isAbsolute());
        assertThrows(IllegalArgumentException.class, () -> Options.parse(List.of("--var"), Map.of(), HOME));
        assertEquals(Path.of("/srv/t/var"), new Options(false, Path.of("/srv/t"), false).var());
    }

    @Test
    void help() {
        assertTrue(Options.parse(List.of("-h"), Map.of(), HOME).help());
        assertTrue(Options.parse(List.of("--daemon", "--help"), Map.of(), HOME).help());
    }

    @Test
    void rejectsUnknownArgumentsAndMissingValues() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Options.parse(List.of("--deamon"), Map.of(), HOME));
        assertEquals("Unknown option: '--deamon'", e.getMessage(), "as the tools' command lines say it (tools.cli)");
        e = assertThrows(IllegalArgumentException.class, () -> Options.parse(List.of("stray"), Map.of(), HOME));
        assertEquals("Unmatched argument: 'stray'", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Options.parse(List.of("--home"), Map.of(), HOME));
        assertThrows(IllegalArgumentException.class, () -> Options.parse(List.of("--home="), Map.of(), HOME));
    }

    /** {@code java -jar tinysep.jar --deamon}: one line naming it, the usage, exit code 2, and no framework started. */
    @Test
    void theLauncherRefusesAnUnknownFlagWithExitCode2() throws Exception {
        java.nio.file.Path err = java.nio.file.Files.createTempFile("launcher-", ".err");
        try {
            Process p = new ProcessBuilder(java.nio.file.Path.of(System.getProperty("java.home"), "bin", "java")
                    .toString(), "-cp", System.getProperty("java.class.path"), Main.class.getName(), "--daemon",
                    "--deamon").redirectError(err.toFile()).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            assertTrue(p.waitFor(60, java.util.concurrent.TimeUnit.SECONDS), "the launcher ends at once");
            String said = java.nio.file.Files.readString(err);
            assertEquals(2, p.exitValue(), said);
            assertEquals("error: Unknown option: '--deamon'", said.lines().findFirst().orElse(""));
            assertTrue(said.contains("--headless"), "the usage follows: " + said);
        } finally {
            java.nio.file.Files.deleteIfExists(err);
        }
    }
}

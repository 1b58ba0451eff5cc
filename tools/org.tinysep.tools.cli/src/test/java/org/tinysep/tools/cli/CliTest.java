package org.tinysep.tools.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Test;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

class CliTest {

    @Command(name = "tool", description = "a tool for the test")
    static final class Tool {
        @Option(names = "--port", converter = OptionTypes.Port.class, description = "a port (default ${DEFAULT-VALUE})")
        int port = 47011;
        @Option(names = "--quiet", description = "say less")
        boolean quiet;
        @Parameters(arity = "0..1", paramLabel = "HOME", description = "the home")
        String home = "A";
    }

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int main(Tool tool, Callable<Integer> body, String... args) {
        return Cli.main(tool, args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), body);
    }

    private String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    @Test
    void anUnknownFlagIsRefusedInOneLineWithTheUsageAndExitCode2() {
        boolean[] ran = {false};
        assertEquals(Cli.USAGE, main(new Tool(), () -> {
            ran[0] = true;
            return 0;
        }, "--colour", "red"));
        assertFalse(ran[0], "the tool does not run");
        String first = err().lines().findFirst().orElseThrow();
        assertEquals("error: Unknown option: '--colour'", first);
        assertTrue(err().contains("--port") && err().contains("a tool for the test"), err());
    }

    @Test
    void helpPrintsTheUsageOnStandardOutputAndExitCode0() {
        assertEquals(Cli.OK, main(new Tool(), () -> 1, "--quiet", "--help"));
        String usage = out.toString(StandardCharsets.UTF_8);
        assertTrue(usage.contains("--port") && usage.contains("default 47011") && usage.contains("-h, --help"), usage);
        assertEquals("", err());
    }

    @Test
    void valuesDefaultsAndTheLastOfARepeatedFlag() {
        Tool t = Cli.parse(new Tool(), "B", "--port", "5000", "--port", "5001");
        assertEquals(5001, t.port);
        assertEquals("B", t.home);
        assertFalse(t.quiet);
        assertEquals(47011, Cli.parse(new Tool()).port);
    }

    @Test
    void badValuesAndStrayArgumentsAreNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Cli.parse(new Tool(), "--port", "70000"));
        assertEquals("Invalid value for option '--port': needs a port 1..65535, not '70000'", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Cli.parse(new Tool(), "A", "B"));
        assertTrue(e.getMessage().contains("'B'"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Cli.parse(new Tool(), "--port"));
        assertTrue(e.getMessage().contains("--port"), e.getMessage());
        assertEquals(Cli.USAGE, main(new Tool(), () -> 0, "--port", "x"));
        assertTrue(err().startsWith("error: Invalid value for option '--port': needs a port 1..65535, not 'x'"), err());
    }

    @Test
    void theRunsOutcomeIsTheExitCode() {
        assertEquals(3, main(new Tool(), () -> 3));
        assertEquals(Cli.USAGE, main(new Tool(), () -> {
            throw new IllegalArgumentException("--until must be after --from");
        }));
        assertTrue(err().startsWith("error: --until must be after --from"), err());
        err.reset();
        assertEquals(Cli.FAILED, main(new Tool(), () -> {
            throw new IOException("no such file: house.xml");
        }));
        assertEquals("error: no such file: house.xml", err().strip());
    }

    @Test
    void sharedTypesRefuseWhatTheyCannotTake() {
        assertEquals(0, new OptionTypes.Count().convert("0"));
        assertThrows(RuntimeException.class, () -> new OptionTypes.Count().convert("-1"));
        assertThrows(RuntimeException.class, () -> new OptionTypes.AtLeastOne().convert("0"));
        assertEquals(42L, new OptionTypes.Seed().convert("42"));
        assertThrows(RuntimeException.class, () -> new OptionTypes.Seed().convert("1.5"));
        assertThrows(RuntimeException.class, () -> new OptionTypes.Port().convert("0"));
    }
}

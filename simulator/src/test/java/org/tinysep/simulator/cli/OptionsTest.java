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
    }

    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
            "--seed abc; --seed needs a number",
            "--from 25:00; --from needs HH:MM",
            "--amica-port 70000; --amica-port needs a port",
            "--speed 0; --speed must be > 0",
            "--date 23.11.2026; --date needs yyyy-mm-dd",
            "--colour red; unknown option(s) [colour]",
            "--from 10:00 --until 09:00; --until must be after --from",
            "stray; unexpected argument 'stray'"})
    void badOptionsAreNamed(String args, String expected) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Options.parse(args.split(" ")));
        assertTrue(e.getMessage().contains(expected), e.getMessage());
    }
}

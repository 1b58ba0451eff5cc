package org.tinysep.drivers.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** {@code tinysep:drivers} with a missing or unknown argument answers with its usage line (issue 32 item 6). */
class DriversCommandsUsageTest {

    /** The usage paths touch neither the framework nor the list. */
    private final DriversCommands commands = new DriversCommands(null, null);

    private String error(org.junit.jupiter.api.function.Executable call) {
        return assertThrows(IllegalArgumentException.class, call).getMessage();
    }

    @Test
    void enableOrDisableWithoutAnApplicationNamesWhatIsMissingAndTheUsage() {
        assertEquals("enable needs the application's bundle symbolic name; " + DriversCommands.USAGE,
                error(() -> commands.drivers("enable")));
        assertEquals("disable needs the application's bundle symbolic name; " + DriversCommands.USAGE,
                error(() -> commands.drivers("DISABLE")));
        assertEquals("use needs the application's bundle symbolic name and the jar; " + DriversCommands.USAGE,
                error(() -> commands.drivers("use", "org.tinysep.door")));
    }

    @Test
    void unknownActionsAndTooManyArgumentsGiveTheUsage() {
        assertEquals("unknown action 'bogus'; " + DriversCommands.USAGE, error(() -> commands.drivers("bogus")));
        assertEquals("unknown action 'bogus'; " + DriversCommands.USAGE, error(() -> commands.drivers("bogus", "x")));
        assertEquals("unknown action 'bogus'; " + DriversCommands.USAGE,
                error(() -> commands.drivers("bogus", "x", "y")));
        assertEquals("wrong number of arguments (4); " + DriversCommands.USAGE,
                error(() -> commands.drivers("a", "b", "c", "d")));
        assertEquals("usage: tinysep:drivers [reload | enable <bsn> | disable <bsn> | use <bsn> <file>] (help"
                + " tinysep:drivers explains them)", DriversCommands.USAGE);
    }
}

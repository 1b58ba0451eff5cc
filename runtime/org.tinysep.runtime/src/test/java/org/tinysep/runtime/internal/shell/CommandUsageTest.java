package org.tinysep.runtime.internal.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.tinysep.runtime.internal.directory.DeviceDirectory;

/** Wrong arguments answer with the usage line, through a real Gogo processor (issue 32 item 6). */
class CommandUsageTest {

    private final GogoShell gogo = new GogoShell().add("tinysep",
            new ShellCommands(new Operations(new DeviceDirectory(), id -> "", 5)), "devices", "remove");

    @Test
    void devicesWithTooManyArgumentsAnswersWithTheUsage() {
        assertEquals("wrong number of arguments (3); usage: tinysep:devices [filter] (help tinysep:devices explains"
                + " them)", gogo.run("tinysep:devices a b c"));
    }

    @Test
    void devicesWithNoneOrOneArgumentStillLists() {
        assertEquals("(no devices)", gogo.run("tinysep:devices"));
        String one = gogo.run("tinysep:devices kitchen");
        assertTrue(one.startsWith("no device matches 'kitchen'"), one);
    }
}

package org.tinysep.runtime.internal.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Collection;
import java.util.List;
import java.util.Map;
import org.apache.felix.service.command.Descriptor;
import org.junit.jupiter.api.Test;

/** {@code help} lists every command the services declare, Function services too (issue 32 item 6). */
class HelpCommandTest {

    /** What the registry holds: one object with methods, and Function services (one name each, hyphens allowed). */
    private static final Collection<Map<String, Object>> SERVICES = List.of(
            Map.of("osgi.command.scope", "tinysep", "osgi.command.function", new String[] {"devices", "set"}),
            Map.of("osgi.command.scope", "tinysep", "osgi.command.function", "rooms"),
            Map.of("osgi.command.scope", "tinysep", "osgi.command.function", "room-add"),
            Map.of("osgi.command.scope", "tinysep", "osgi.command.function", "web-password"),
            Map.of("osgi.command.scope", "felix", "osgi.command.function", List.of("help", "lb")));

    /** Stands in for gogo.command's felix:help: it lists only what its service has methods for. */
    public static final class GogoHelp {
        @Descriptor("Gogo's")
        public String help() {
            return "felix:help\nfelix:lb\ntinysep:devices\ntinysep:set";
        }

        @Descriptor("Gogo's, one command")
        public String help(String command) {
            return "explains " + command;
        }
    }

    @Test
    void namesEveryDeclaredCommandSortedOnce() {
        assertEquals(List.of("felix:help", "felix:lb", "tinysep:devices", "tinysep:room-add", "tinysep:rooms",
                "tinysep:set", "tinysep:web-password"), HelpCommand.names(SERVICES));
    }

    @Test
    void plainHelpInTheShellIsThisOneRankedAboveGogosAndHelpWithANameIsGogos() {
        GogoHelp gogoHelp = new GogoHelp();
        GogoShell gogo = new GogoShell().add("felix", gogoHelp, 0, "help", "lb")
                .add("felix", new HelpCommand(() -> SERVICES, gogoHelp::help), 1, "help");
        String all = gogo.run("help");
        for (String c : List.of("tinysep:rooms", "tinysep:room-add", "tinysep:web-password", "tinysep:devices")) {
            assertTrue(all.lines().anyMatch(c::equals), c + " missing from:\n" + all);
        }
        assertEquals("explains tinysep:devices", gogo.run("help tinysep:devices"));
        assertTrue(gogo.run("help 'a;b'").startsWith("not a command name"));
    }
}

package org.tinysep.runtime.internal.shell;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.apache.felix.gogo.runtime.CommandProcessorImpl;
import org.apache.felix.service.command.CommandSession;

/**
 * A real Gogo command processor (the runtime the platform ships), so a test sees which of a command's methods Gogo
 * picks for a line and what the user reads, e.g. "Cannot coerce" when no method takes the arguments.
 */
public final class GogoShell {

    private final CommandProcessorImpl processor = new CommandProcessorImpl();

    /** Registers {@code target}'s methods named {@code functions} under {@code scope}. */
    public GogoShell add(String scope, Object target, String... functions) {
        return add(scope, target, 0, functions);
    }

    /** The same with a service ranking: for a name in two scopes, Gogo runs the higher ranked one. */
    public GogoShell add(String scope, Object target, int ranking, String... functions) {
        for (String f : functions) {
            processor.addCommand(scope, target, f, ranking);
        }
        return this;
    }

    /** @return the command's result as text, or the message of what it threw (one line, as Gogo prints it) */
    public String run(String line) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(out, true, StandardCharsets.UTF_8);
        try (CommandSession session = processor.createSession(new ByteArrayInputStream(new byte[0]), print, print)) {
            return String.valueOf(session.execute(line));
        } catch (Exception e) {
            return e.getMessage();
        }
    }
}

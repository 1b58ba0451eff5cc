package org.tinysep.tools.cli;

import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * One way for every tool's command line: a picocli command object ({@code @Command}, {@code @Option},
 * {@code @Parameters} fields) is filled from the arguments, and
 * <ul>
 * <li>an unknown flag, a missing or bad value, a stray argument: one line {@code error: Unknown option: '--colour'},
 * the usage, exit code {@value #USAGE};</li>
 * <li>{@code --help} or {@code -h}: the usage on standard output, exit code {@value #OK};</li>
 * <li>the run throws {@link IllegalArgumentException} (a combination the types cannot check, e.g. {@code --until}
 * before {@code --from}): as a bad value, exit code {@value #USAGE}; any other exception: {@code error: <message>},
 * exit code {@value #FAILED}.</li>
 * </ul>
 * A flag given twice takes its last value (scripts put their defaults first and pass the user's arguments after them);
 * {@code @file} arguments are not expanded.
 */
public final class Cli {

    /** The run succeeded, or {@code --help}. */
    public static final int OK = 0;
    /** The run failed. */
    public static final int FAILED = 1;
    /** The command line was refused. */
    public static final int USAGE = 2;

    private Cli() {
    }

    /**
     * Fills {@code command}'s options from {@code args}, for a caller that runs the command itself (a test, another
     * program). {@code --help} is parsed like any flag (the command's {@code usageHelp} field is set).
     *
     * @return {@code command}
     * @throws IllegalArgumentException with one line naming the flag or argument that is refused
     */
    public static <T> T parse(T command, String... args) {
        try {
            commandLine(command).parseArgs(args);
            return command;
        } catch (CommandLine.ParameterException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    /** @return the usage text of {@code command}, as {@code --help} prints it */
    public static String usage(Object command) {
        return commandLine(command).getUsageMessage(CommandLine.Help.Ansi.OFF);
    }

    /**
     * A tool's {@code main}: parses {@code args} into {@code command}, then runs {@code body}.
     *
     * @return the exit code: {@link #OK}, {@link #FAILED}, {@link #USAGE} or {@code body}'s own
     */
    public static int main(Object command, String[] args, PrintStream out, PrintStream err, Callable<Integer> body) {
        CommandLine line = commandLine(command);
        try {
            line.parseArgs(args);
        } catch (CommandLine.ParameterException e) {
            return refused(command, e.getMessage(), err);
        }
        if (line.isUsageHelpRequested()) {
            out.print(usage(command));
            out.flush();
            return OK;
        }
        return run(command, body, err);
    }

    /**
     * Runs {@code body} (which parsed its own arguments, e.g. a sub-command) and maps its outcome as {@link #main}
     * does; {@code command} gives the usage printed after a refused argument.
     */
    public static int run(Object command, Callable<Integer> body, PrintStream err) {
        try {
            return body.call();
        } catch (IllegalArgumentException e) {
            return refused(command, e.getMessage(), err);
        } catch (Exception e) {
            err.println("error: " + (e.getMessage() != null ? e.getMessage() : e.toString()));
            if (e.getMessage() == null || e instanceof RuntimeException && !(e instanceof IllegalStateException)
                    && !(e instanceof UncheckedIOException)) {
                e.printStackTrace(err); // a bug rather than a situation: where it happened
            }
            err.flush();
            return FAILED;
        }
    }

    private static int refused(Object command, String message, PrintStream err) {
        err.println("error: " + message);
        err.print(usage(command));
        err.flush();
        return USAGE;
    }

    private static CommandLine commandLine(Object command) {
        CommandLine line = new CommandLine(command);
        CommandSpec spec = line.getCommandSpec();
        if (spec.options().stream().noneMatch(OptionSpec::usageHelp)) {
            spec.addOption(OptionSpec.builder("-h", "--help").usageHelp(true).description("print this text").build());
        }
        line.setOverwrittenOptionsAllowed(true);
        line.setExpandAtFiles(false);
        line.setUsageHelpWidth(120);
        return line;
    }
}

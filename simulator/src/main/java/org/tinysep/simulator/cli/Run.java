package org.tinysep.simulator.cli;

/**
 * Runs a simulation from code (an integration test, another program) with the command line's options, without
 * {@code System.exit}: returns when the simulated span is played, throws on bad options or a failed run.
 */
public final class Run {

    private Run() {
    }

    /**
     * @param args the options of {@link Main} (see the README), e.g. {@code --lockstep --sync-port 40000}
     * @throws IllegalArgumentException on bad options
     * @throws Exception when the simulation cannot start or fails (the platform refuses lock-step, a file is bad)
     */
    public static void simulate(String... args) throws Exception {
        Main.run(Options.parse(args));
    }

    /**
     * Replays a recorded home ({@code --replay <file>}, see the README) and returns what was played, so that a test
     * can map the platform's virtual times back onto the recording.
     *
     * @throws IllegalArgumentException on bad options or when {@code --replay} is missing
     */
    public static ReplayResult replay(String... args) throws Exception {
        Options o = Options.parse(args);
        if (o.replay() == null) {
            throw new IllegalArgumentException("--replay <file> is needed");
        }
        return ReplayRunner.run(o);
    }
}

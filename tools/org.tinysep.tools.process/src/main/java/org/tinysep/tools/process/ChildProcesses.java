package org.tinysep.tools.process;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Every child process started through this library (and any other a caller hands to {@link #track}): a harness or
 * test that ends early (an error, Ctrl-C) must not leave a platform behind, so a shutdown hook kills what still runs.
 * A child leaves the set when it exits.
 */
public final class ChildProcesses {

    private static final Set<Process> LIVE = ConcurrentHashMap.newKeySet();

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> LIVE.forEach(Process::destroyForcibly),
                "tinysep-children-stop"));
    }

    private ChildProcesses() {
    }

    /** Registers {@code p} until it exits. @return p */
    public static Process track(Process p) {
        LIVE.add(p);
        p.onExit().thenRun(() -> LIVE.remove(p));
        return p;
    }

    /** @return how many tracked children still run */
    public static int running() {
        return (int) LIVE.stream().filter(Process::isAlive).count();
    }
}

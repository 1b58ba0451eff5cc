package org.tinysep.benchmarks;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/** Every process the benchmarks started: ended by a shutdown hook if the run is stopped (Ctrl-C) midway. */
final class Children {

    private static final Set<Process> LIVE = ConcurrentHashMap.newKeySet();

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> LIVE.forEach(Process::destroyForcibly),
                "benchmarks-children"));
    }

    private Children() {
    }

    static Process track(Process p) {
        LIVE.add(p);
        p.onExit().thenRun(() -> LIVE.remove(p));
        return p;
    }
}

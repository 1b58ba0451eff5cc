package org.tinysep.runtime.internal;

import java.util.concurrent.Executors;
import java.util.concurrent.ThreadFactory;

/** Thread factories for the runtime's executors: named daemon threads. */
public final class Threads {

    private Threads() {
    }

    public static ThreadFactory named(String name) {
        ThreadFactory base = Executors.defaultThreadFactory();
        return r -> {
            Thread t = base.newThread(r);
            t.setName(name);
            t.setDaemon(true);
            return t;
        };
    }
}

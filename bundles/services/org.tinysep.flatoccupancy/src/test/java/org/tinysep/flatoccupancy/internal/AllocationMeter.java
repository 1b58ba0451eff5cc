package org.tinysep.flatoccupancy.internal;

import java.lang.management.ManagementFactory;

/**
 * Bytes the current thread allocates per call of a piece of work (the JVM's per-thread allocation counter,
 * {@code com.sun.management.ThreadMXBean}). Warms the work up first: class loading and first-call caches are no
 * per-call cost.
 */
final class AllocationMeter {

    private AllocationMeter() {
    }

    /** @return the bytes allocated per call, averaged over {@code calls} calls after as many warm-up calls */
    static double bytesPerCall(int calls, Runnable work) {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        for (int i = 0; i < calls; i++) {
            work.run();
        }
        long id = Thread.currentThread().getId();
        long before = mx.getThreadAllocatedBytes(id);
        for (int i = 0; i < calls; i++) {
            work.run();
        }
        return (mx.getThreadAllocatedBytes(id) - before) / (double) calls;
    }
}

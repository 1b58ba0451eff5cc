package org.tinysep.device.support.testing;

import java.lang.management.ManagementFactory;

/**
 * Bytes the current thread allocates per call of a piece of work (the JVM's own per-thread allocation counter,
 * {@code com.sun.management.ThreadMXBean}): the cost tests of issue 29 item 1 (work per frame on the radio's
 * threads) read it. Warms the work up first (class loading and first-call caches are no per-call cost).
 */
public final class AllocationMeter {

    private AllocationMeter() {
    }

    /** @return the bytes allocated per call, averaged over {@code calls} calls after as many warm-up calls */
    public static double bytesPerCall(int calls, Runnable work) {
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

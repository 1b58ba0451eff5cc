package org.tinysep.testsupport.wait;

import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

/** Waiting on a condition instead of sleeping: polls every 10 ms and fails after 10 s, naming what it waited for. */
public final class Await {

    private Await() {
    }

    /**
     * @param condition what must become true
     * @param what      what it means, for the failure message
     * @throws AssertionError "timed out after 10 s waiting for {@code what}"
     */
    public static void until(BooleanSupplier condition, String what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out after 10 s waiting for " + what);
            }
            Thread.sleep(10);
        }
    }
}

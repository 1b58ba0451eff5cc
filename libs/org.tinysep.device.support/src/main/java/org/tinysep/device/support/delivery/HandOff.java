package org.tinysep.device.support.delivery;

import java.time.Duration;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;

/**
 * The ordered queue between the receive thread and {@link OrderedDelivery}'s dispatcher: a bounded lock-free queue,
 * and a wake-up only when the dispatcher sleeps. While payloads come faster than {@link #SPIN} apart, a dispatcher
 * that finds the queue empty first yields its core for up to that long (the next payload of a burst usually comes
 * within it) and only then parks: under load the receive thread wakes it once per burst rather than once per
 * payload ({@link #wakeups()}); at a slower pace it parks at once, so an idle radio costs no CPU.
 */
final class HandOff {

    /** How long an idle dispatcher yields and looks again before it parks. */
    static final Duration SPIN = Duration.ofNanos(30_000);

    private final int capacity;
    private final ConcurrentLinkedQueue<OrderedDelivery.Job<?>> queue = new ConcurrentLinkedQueue<>();
    private final AtomicInteger queued = new AtomicInteger();
    /** The dispatcher's thread while it parks (or is about to); the submitter that takes it out wakes it. */
    private final AtomicReference<Thread> sleeper = new AtomicReference<>();
    private final AtomicLong wakeups = new AtomicLong();
    private final AtomicLong spinsInVain = new AtomicLong();
    private volatile long spinNanos = SPIN.toNanos();
    private long lastWait; // the dispatcher's: how long its last take() waited for a job

    HandOff(int capacity) {
        this.capacity = capacity;
    }

    /**
     * On the receive thread; never blocks. {@code accepted} runs once the job is sure to be queued, before the
     * dispatcher can see it.
     *
     * @return false when the queue was full
     */
    boolean offer(OrderedDelivery.Job<?> job, Runnable accepted) {
        if (queued.incrementAndGet() > capacity) {
            queued.decrementAndGet();
            return false;
        }
        accepted.run();
        queue.offer(job);
        Thread s = sleeper.get();
        if (s != null && sleeper.compareAndSet(s, null)) {
            wakeups.incrementAndGet();
            LockSupport.unpark(s);
        }
        return true;
    }

    /**
     * The dispatcher: the next job, waiting for one. It yields and looks again for up to {@link #SPIN} only while
     * payloads come that fast (its last wait was shorter than that), else it parks at once: at a slower pace a
     * spin would only burn a core the receive thread may need.
     *
     * @param closed whether the delivery closed (then it stops waiting)
     */
    OrderedDelivery.Job<?> take(java.util.function.BooleanSupplier closed) throws InterruptedException {
        OrderedDelivery.Job<?> j = poll();
        if (j != null) {
            lastWait = 0;
            return j;
        }
        long start = System.nanoTime();
        long spin = spinNanos;
        if (lastWait < spin) {
            while (System.nanoTime() - start < spin) {
                Thread.yield();
                if ((j = poll()) != null) {
                    lastWait = System.nanoTime() - start;
                    return j;
                }
            }
            spinsInVain.incrementAndGet();
        }
        Thread me = Thread.currentThread();
        while (true) {
            sleeper.set(me); // then look again: a job offered before this is seen, one offered after it wakes us
            if ((j = poll()) != null) {
                sleeper.compareAndSet(me, null);
                lastWait = System.nanoTime() - start;
                return j;
            }
            LockSupport.park(this);
            if (Thread.interrupted() || closed.getAsBoolean()) {
                sleeper.compareAndSet(me, null);
                throw new InterruptedException("closed");
            }
        }
    }

    private OrderedDelivery.Job<?> poll() {
        OrderedDelivery.Job<?> j = queue.poll();
        if (j != null) {
            queued.decrementAndGet();
        }
        return j;
    }

    /** @return payloads waiting for the dispatcher */
    int queued() {
        return queued.get();
    }

    /** For tests: how long an idle dispatcher yields before it parks (0: parks at once). */
    void spin(Duration d) {
        spinNanos = d.toNanos();
    }

    /** @return how often an idle dispatcher yielded for {@link #SPIN} and then parked all the same */
    long spinsInVain() {
        return spinsInVain.get();
    }

    /** @return how often a submitter woke a parked dispatcher */
    long wakeups() {
        return wakeups.get();
    }
}

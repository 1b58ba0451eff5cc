package org.tinysep.device.support.delivery;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * A slow consumer never stalls the radio, and the order of payloads across the devices of one radio is
 * kept. The receive thread only decodes and {@link #submit submits} a {@link Job} per payload to ONE bounded queue;
 * one dispatcher thread takes the jobs in order and calls each job's listeners ({@link GuardedLane}) in turn.
 * <p>
 * A watchdog looks every quarter of the slow-call limit while a payload is in hand (an idle delivery wakes no
 * thread for it: the first payload after a pause starts its rounds again): a listener that has been inside one call
 * longer than the limit is <em>quarantined</em>. The dispatcher thread stays with it (the call goes on), a fresh dispatcher takes
 * over the queue where it was (the rest of that job's listeners, then the next jobs), and the quarantined listener
 * gets its payloads through its own small bounded queue until it keeps up again. The healthy listeners keep their
 * order across devices. A full queue never blocks the receive thread: the payload is dropped, counted and said as
 * a {@code PROBLEM} at most once a minute. {@link #awaitDelivered} lets a lock-step tick wait until what was
 * submitted before it reached its listeners (handed to a quarantined one's queue counts as reached).
 * <p>
 * The hand-off is cheap for the receive thread: a lock-free queue, and a wake-up only when the dispatcher sleeps
 * ({@link HandOff}).
 * <p>
 * The executor and the watchdog are this object's; {@link #close()} (the driver's deactivate) shuts them down.
 */
public final class OrderedDelivery implements AutoCloseable {

    /** Default: a listener inside one call longer than this is taken out of the ordered path. */
    public static final Duration SLOW_CALL = Duration.ofSeconds(1);
    /** Default capacity of the ordered queue (payloads waiting for the dispatcher). */
    public static final int CAPACITY = 16_384;
    /** Default capacity of a quarantined listener's own queue. */
    public static final int LANE_CAPACITY = 1_024;
    static final long REPORT_NANOS = 60_000_000_000L;

    private static final Logger LOG = LoggerFactory.getLogger(OrderedDelivery.class);

    private final DriverContext context;
    private final String radio;
    private final long slowNanos;
    private final int laneCapacity;
    private final int capacity;
    private final HandOff handOff;
    private final ExecutorService pool;
    private final ScheduledExecutorService watchdog;
    private final AtomicLong submitted = new AtomicLong();
    /** Whether the watchdog's next round is scheduled; rounds stop while nothing is in hand. */
    private final AtomicBoolean armed = new AtomicBoolean();
    private final AtomicLong watchRounds = new AtomicLong();
    private final long watchPeriod;
    private final AtomicLong completed = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    private final AtomicLong quarantines = new AtomicLong();
    private final RateLimitedProblem full = new RateLimitedProblem();
    private volatile Dispatcher worker;
    private volatile Thread waiter;
    private volatile long waitFor;
    private volatile boolean closed;

    /** @param radio names the radio in what the user reads, e.g. "The AmICA UDP radio" */
    public OrderedDelivery(DriverContext context, String radio, Duration slowCall, int capacity, int laneCapacity) {
        if (slowCall.isNegative() || slowCall.isZero() || capacity < 1 || laneCapacity < 1) {
            throw new IllegalArgumentException("slow-call limit and capacities must be positive: " + slowCall + ", "
                    + capacity + ", " + laneCapacity);
        }
        this.context = context;
        this.radio = radio;
        this.slowNanos = slowCall.toNanos();
        this.laneCapacity = laneCapacity;
        AtomicInteger n = new AtomicInteger();
        String threads = context.driverName() + "-deliver-";
        this.pool = Executors.newCachedThreadPool(r -> daemon(r, threads + n.incrementAndGet()));
        this.watchdog = Executors.newSingleThreadScheduledExecutor(r -> daemon(r, context.driverName() + "-watchdog"));
        this.watchPeriod = Math.max(10_000_000L, slowNanos / 4);
        this.capacity = capacity;
        this.handOff = new HandOff(capacity);
        this.worker = new Dispatcher(null, this);
        pool.execute(worker);
    }

    public OrderedDelivery(DriverContext context, String radio) {
        this(context, radio, SLOW_CALL, CAPACITY, LANE_CAPACITY);
    }

    private static Thread daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    /** Queues a job in order; never blocks. @return false when the queue was full (dropped, counted, said) */
    public boolean submit(Job<?> job) {
        // counted before it can be completed (awaitDelivered compares the two)
        if (handOff.offer(job, submitted::incrementAndGet)) {
            if (!armed.get() && armed.compareAndSet(false, true)) {
                scheduleWatch();
            }
            return true;
        }
        dropped.incrementAndGet();
        String words = full.drop(Instant.now(), (count, since) -> radio + " cannot hand payloads to its devices fast"
                + " enough: " + count + " payload" + (count == 1 ? "" : "s") + " dropped since " + since + " (its"
                + " queue of " + capacity + " was full). The radio goes on receiving;"
                + " what was dropped is lost. The computer may be overloaded");
        if (words != null) {
            LOG.warn("{}", words);
            context.event(EventKind.PROBLEM, words);
        }
        return false;
    }

    /**
     * Waits until every job submitted before this call has been given to its listeners (to a quarantined one's
     * own queue counts), at most {@code max}. One waiter at a time (the platform tick).
     *
     * @return whether they all had
     */
    public boolean awaitDelivered(Duration max) {
        long target = submitted.get();
        if (completed.get() >= target) {
            return true;
        }
        long end = System.nanoTime() + max.toNanos();
        waitFor = target;
        waiter = Thread.currentThread();
        try {
            while (completed.get() < target && !closed) {
                long left = end - System.nanoTime();
                if (left <= 0) {
                    return false;
                }
                watch();
                LockSupport.parkNanos(Math.min(left, 5_000_000L));
            }
            return completed.get() >= target;
        } finally {
            waiter = null;
        }
    }

    private void scheduleWatch() {
        try {
            watchdog.schedule(this::watchRound, watchPeriod, TimeUnit.NANOSECONDS);
        } catch (RejectedExecutionException e) { // closed
            armed.set(false);
        }
    }

    /**
     * One round of the watchdog; the next follows while a payload submitted is not yet delivered. Otherwise the
     * rounds stop, and the next {@link #submit} starts them: it counts its payload before it looks whether they
     * run, and this looks again after it stopped them, so a payload is never left without a watchdog.
     */
    private void watchRound() {
        watchRounds.incrementAndGet();
        watch();
        if (completed.get() < submitted.get()) {
            scheduleWatch();
            return;
        }
        armed.set(false);
        if (completed.get() < submitted.get() && armed.compareAndSet(false, true)) {
            scheduleWatch();
        }
    }

    /** @return the watchdog's rounds so far (tests: none while the delivery is idle) */
    long watchRounds() {
        return watchRounds.get();
    }

    /** The watchdog: a listener inside one call longer than the limit leaves the ordered path. */
    void watch() {
        Dispatcher w = worker;
        GuardedLane<?> lane = w.quarantineIfSlow(slowNanos);
        if (lane == null) {
            return;
        }
        quarantines.incrementAndGet();
        Dispatcher next = new Dispatcher(w.job, this);
        worker = next;
        try {
            pool.execute(next);
        } catch (RejectedExecutionException e) { // closed meanwhile
            return;
        }
        lane.quarantined(Duration.ofNanos(slowNanos));
    }

    boolean closed() {
        return closed;
    }

    /** The dispatcher: the next job, waiting for one ({@link HandOff#take}). */
    Job<?> take() throws InterruptedException {
        return handOff.take(this::closed);
    }

    /** For tests: how long an idle dispatcher yields before it parks (0: parks at once). */
    void spin(Duration d) {
        handOff.spin(d);
    }

    /** @return how often an idle dispatcher yielded for {@link HandOff#SPIN} and then parked all the same */
    long spinsInVain() {
        return handOff.spinsInVain();
    }

    /** @return how often a submitter woke a parked dispatcher */
    public long wakeups() {
        return handOff.wakeups();
    }

    void done() {
        long c = completed.incrementAndGet();
        Thread t = waiter;
        if (t != null && c >= waitFor) {
            LockSupport.unpark(t);
        }
    }

    void execute(Runnable r) {
        pool.execute(r);
    }

    int laneCapacity() {
        return laneCapacity;
    }

    DriverContext context() {
        return context;
    }

    /** @return payloads dropped because the ordered queue or a quarantined listener's queue was full */
    public long dropped() {
        return dropped.get();
    }

    void droppedForLane() {
        dropped.incrementAndGet();
    }

    /** @return how often a listener was taken out of the ordered path */
    public long quarantines() {
        return quarantines.get();
    }

    /** @return the counters for the driver's parameters */
    public List<Parameter> parameters() {
        return List.of(Parameter.readOnly("delivery.queued", handOff.queued(), "payloads waiting for the dispatcher"),
                Parameter.readOnly("delivery.dropped", dropped.get(), "payloads dropped: a queue was full"),
                Parameter.readOnly("delivery.slowListeners", quarantines.get(),
                        "times a listener took over " + slowNanos / 1_000_000 + " ms and got its own queue"));
    }

    @Override
    public void close() {
        closed = true;
        watchdog.shutdownNow();
        pool.shutdownNow();
    }

    /** Runs a job on the caller's thread (a radio without a dispatcher): same order, no watchdog. */
    public static void inline(Job<?> job) {
        new Dispatcher(null, null).run(job);
    }

    /** One payload for the listeners {@link #begin()} names, in their order. */
    public abstract static class Job<T> {
        final T item;
        List<? extends GuardedLane<T>> targets;
        int next = -1;

        protected Job(T item) {
            this.item = item;
        }

        /** On the dispatcher, once: @return the listeners to give the payload to, in order */
        protected abstract List<? extends GuardedLane<T>> begin();

        /**
         * The lane closed before the payload reached it (its listener left).
         *
         * @return further lanes to give it to (e.g. a replacement that connected since {@link #begin()})
         */
        protected abstract List<? extends GuardedLane<T>> missed(GuardedLane<T> lane);

        public T item() {
            return item;
        }
    }
}

package org.tinysep.device.support.delivery;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Device;
import org.tinysep.api.log.EventKind;

/**
 * One listener as the {@link OrderedDelivery} dispatcher sees it. Normally called directly, in order, by the
 * dispatcher. Once the watchdog found it inside one call longer than the limit it is <em>quarantined</em>: the
 * dispatcher only puts its payloads into its own bounded queue (a full queue drops, counted and said at most once
 * a minute), a pool thread gives them to it in order, and it rejoins the ordered path when its queue is empty and
 * its last call was quick (under a tenth of the limit). Closing it (its listener leaves) hands back what it had
 * not been given yet.
 *
 * @param <T> the payload type
 */
public abstract class GuardedLane<T> {

    private static final Logger LOG = LoggerFactory.getLogger(GuardedLane.class);

    private volatile OrderedDelivery delivery; // set when quarantined (by the dispatcher that retired)
    private final ArrayDeque<OrderedDelivery.Job<T>> backlog = new ArrayDeque<>();
    private final RateLimitedProblem drops = new RateLimitedProblem();
    private final RateLimitedProblem slowCalls = new RateLimitedProblem();
    private boolean closed; // guarded by this
    private boolean quarantined; // guarded by this
    private boolean draining; // guarded by this
    private volatile long lastCallNanos;
    private volatile long quickNanos = Long.MAX_VALUE;

    /** Gives the payload to the listener. */
    protected abstract void call(T item);

    /** @return the listener in words, e.g. "The listener 'Movement 1.17' of AmICA node 1.17" */
    protected abstract String describe();

    /** @return whether it is out of the ordered path now */
    public synchronized boolean quarantined() {
        return quarantined;
    }

    /** On the dispatcher. @return false when the watchdog retired this dispatcher during the call */
    final boolean fromDispatcher(OrderedDelivery.Job<T> job, Dispatcher worker) {
        boolean missed = false;
        boolean rejoined = false;
        synchronized (this) {
            if (closed) {
                missed = true;
            } else if (quarantined) {
                if (!backlog.isEmpty() || draining || lastCallNanos >= quickNanos) {
                    enqueue(job);
                    return true;
                }
                quarantined = false; // kept up: the dispatcher is the only producer, its queue is empty and idle
                rejoined = true;
            }
        }
        if (missed) {
            List<? extends GuardedLane<T>> more = job.missed(this);
            if (!more.isEmpty()) {
                List<GuardedLane<T>> all = new ArrayList<>(job.targets);
                all.addAll(more);
                job.targets = all;
            }
            return true;
        }
        if (rejoined) {
            String words = describe() + " keeps up again: it is back in the ordered path with the other devices";
            LOG.info("{}", words);
            delivery.context().event(EventKind.DEVICE_EVENT, words);
        }
        worker.enter(this);
        invoke(job.item);
        if (!worker.leave()) { // quarantined during the call: this thread now serves its own queue
            lastCallNanos = quickNanos; // the slow call itself does not count as keeping up
            drain();
            return false;
        }
        return true;
    }

    private void enqueue(OrderedDelivery.Job<T> job) { // holds this
        if (backlog.size() >= delivery.laneCapacity()) {
            delivery.droppedForLane();
            String words = drops.drop(Instant.now(), (n, since) -> describe() + " is too slow: " + n + " payload"
                    + (n == 1 ? "" : "s") + " for it dropped since " + since + " (its own queue of "
                    + delivery.laneCapacity() + " was full). The radio goes on receiving and the other devices are"
                    + " served in order; what this one missed is lost");
            if (words != null) {
                LOG.warn("{}", words);
                delivery.context().event(EventKind.PROBLEM, words);
            }
            return;
        }
        backlog.add(job);
        if (!draining) {
            draining = true;
            delivery.execute(this::drain);
        }
    }

    private void drain() {
        while (true) {
            OrderedDelivery.Job<T> j;
            synchronized (this) {
                j = closed ? null : backlog.poll();
                if (j == null) {
                    draining = false;
                    return;
                }
            }
            long start = System.nanoTime();
            invoke(j.item);
            lastCallNanos = System.nanoTime() - start;
        }
    }

    private void invoke(T item) {
        try {
            call(item);
        } catch (RuntimeException | LinkageError e) {
            LOG.warn("{} failed: {}", describe(), e.toString());
            LOG.debug("Listener failure detail", e);
        }
    }

    /** The watchdog, holding the dispatcher's lock: this listener's current call is too slow. */
    final synchronized void takeOut(OrderedDelivery owner) {
        delivery = owner;
        quarantined = true;
        draining = true; // the retired dispatcher's thread serves the queue once the slow call returns
    }

    /** Says that it was taken out (at most once a minute per listener). */
    final void quarantined(Duration limit) {
        quickNanos = limit.toNanos() / 10;
        if (slowCalls.mayReport()) {
            String words = describe() + " has been busy with one payload for over " + limit.toMillis() + " ms. So"
                    + " that the radio and the other devices do not wait for it, it now gets its payloads through its"
                    + " own queue (at most " + delivery.laneCapacity() + " waiting; more are dropped and counted) and"
                    + " rejoins the others when it keeps up";
            LOG.warn("{}", words);
            delivery.context().event(EventKind.PROBLEM, words);
        }
    }

    /** The listener left: it gets nothing more. @return what was queued for it and not given yet, oldest first */
    protected final synchronized List<OrderedDelivery.Job<T>> shut() {
        closed = true;
        List<OrderedDelivery.Job<T>> left = new ArrayList<>(backlog);
        backlog.clear();
        return left;
    }

    /**
     * @return a listener in plain words for the lane's {@link #describe()}: a device by its name, anything else by
     *         its class (a lambda by the class that made it), e.g. {@code "The listener 'Movement 1.17' of AmICA node 1.17"}
     */
    protected static String listenerWords(Object listener, String node) {
        String name = listener instanceof Device d ? "'" + d.name() + "'" : listener.getClass().getName();
        int lambda = name.indexOf("$$");
        return "The listener " + (lambda > 0 ? name.substring(name.lastIndexOf('.', lambda) + 1, lambda) : name)
                + " of " + node;
    }

    protected final synchronized boolean isClosed() {
        return closed;
    }
}

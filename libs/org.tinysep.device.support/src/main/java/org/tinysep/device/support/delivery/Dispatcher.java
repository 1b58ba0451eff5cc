package org.tinysep.device.support.delivery;

/**
 * A dispatcher of {@link OrderedDelivery}: drains the ordered queue, one job after the other and each job's
 * listeners in order, until the watchdog retires it in a slow call; its thread then stays with that listener
 * ({@link GuardedLane}) and a fresh dispatcher goes on where it was. Without an owner it runs one job on the
 * caller's thread ({@link OrderedDelivery#inline}).
 */
final class Dispatcher implements Runnable {
    private final OrderedDelivery owner;
    private OrderedDelivery.Job<?> resume;
    OrderedDelivery.Job<?> job;
    private volatile GuardedLane<?> inCall;
    private volatile long callStart;
    private boolean retired; // guarded by this

    Dispatcher(OrderedDelivery.Job<?> resume, OrderedDelivery owner) {
        this.resume = resume;
        this.owner = owner;
    }

    @Override
    public void run() {
        OrderedDelivery o = owner;
        OrderedDelivery.Job<?> j = resume;
        if (j != null) {
            j.next++; // the slow listener had it
        }
        try {
            while (!o.closed()) {
                if (j == null) {
                    j = o.take();
                }
                if (!run(j)) {
                    return; // retired: this thread stays with the quarantined listener (GuardedLane)
                }
                j = null;
                o.done();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt(); // closed
        }
    }

    <T> boolean run(OrderedDelivery.Job<T> j) {
        job = j;
        if (j.next < 0) {
            j.targets = j.begin();
            j.next = 0;
        }
        while (j.next < j.targets.size()) {
            GuardedLane<T> lane = j.targets.get(j.next);
            if (!lane.fromDispatcher(j, this)) {
                return false;
            }
            j.next++;
        }
        return true;
    }

    void enter(GuardedLane<?> lane) {
        callStart = System.nanoTime();
        inCall = lane;
    }

    /** @return false when the watchdog retired this dispatcher during the call */
    synchronized boolean leave() {
        inCall = null;
        return !retired;
    }

    synchronized GuardedLane<?> quarantineIfSlow(long limit) {
        GuardedLane<?> lane = inCall;
        if (lane == null || retired || System.nanoTime() - callStart <= limit) {
            return null;
        }
        retired = true;
        lane.takeOut(owner);
        return lane;
    }
}

package org.tinysep.device.support.delivery;

import java.util.List;

/** A test payload for fixed lanes, in their order; a lane that left misses it (no replacement). */
final class ToLanes<T> extends OrderedDelivery.Job<T> {
    private final List<? extends GuardedLane<T>> to;

    @SafeVarargs
    ToLanes(T item, GuardedLane<T>... to) {
        super(item);
        this.to = List.of(to);
    }

    @Override
    protected List<? extends GuardedLane<T>> begin() {
        return to;
    }

    @Override
    protected List<? extends GuardedLane<T>> missed(GuardedLane<T> lane) {
        return List.of();
    }
}

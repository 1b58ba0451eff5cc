package org.tinysep.runtime.internal.log;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.LongFunction;

/**
 * A bounded, thread-safe ring of log entries. Each appended entry gets the next sequence number (the first is 1,
 * then one more each time, with no gaps); when full, the oldest entry is dropped. Appending is O(1); the lock is
 * held only to store a reference, never while calling foreign code.
 *
 * @param <E> the entry type
 */
final class RingBuffer<E> {

    /** Largest accepted capacity; a bigger log belongs on disk, not in memory. */
    static final int MAX_CAPACITY = 5_000_000;

    private Object[] slots;
    private int head; // index of the oldest entry
    private int size;
    private long lastSequence; // 0 while empty
    private volatile int capacityHint; // the capacity, readable without the lock

    RingBuffer(int capacity) {
        slots = new Object[check(capacity)];
        capacityHint = capacity;
    }

    /**
     * Appends the entry built by {@code factory} from the next sequence number. The factory runs under the lock:
     * it must only build a value object (no I/O, no calls into other bundles). If it throws, nothing changes.
     *
     * @return the appended entry
     */
    synchronized E append(LongFunction<E> factory) {
        long sequence = lastSequence + 1;
        E entry = factory.apply(sequence);
        lastSequence = sequence;
        if (size < slots.length) {
            slots[(head + size) % slots.length] = entry;
            size++;
        } else {
            slots[head] = entry;
            head = (head + 1) % slots.length;
        }
        return entry;
    }

    /** @return the newest {@code max} entries, oldest first; empty for {@code max <= 0} */
    synchronized List<E> newest(int max) {
        int n = Math.min(Math.max(max, 0), size);
        return copy(size - n, n);
    }

    /** @return up to {@code max} entries whose sequence is greater than {@code sequence}, oldest first */
    synchronized List<E> after(long sequence, int max) {
        long oldest = lastSequence - size + 1;
        long from = Math.max(sequence + 1, oldest);
        if (max <= 0 || from > lastSequence) {
            return List.of();
        }
        int n = (int) Math.min(max, lastSequence - from + 1);
        return copy((int) (from - oldest), n);
    }

    /**
     * Fills an empty ring with entries loaded from the history (oldest first; only the newest that fit are kept)
     * and makes numbering go on after {@code lastSequence}.
     *
     * @throws IllegalStateException when the ring is not empty
     */
    synchronized void restore(List<E> entries, long lastSequence) {
        if (size > 0 || this.lastSequence > 0) {
            throw new IllegalStateException("only an empty ring can be restored");
        }
        int n = Math.min(entries.size(), slots.length);
        for (int i = 0; i < n; i++) {
            slots[i] = entries.get(entries.size() - n + i);
        }
        head = 0;
        size = n;
        this.lastSequence = Math.max(lastSequence, 0);
    }

    /** Changes the capacity, keeping the newest entries; sequence numbering goes on unchanged. */
    synchronized void resize(int capacity) {
        check(capacity);
        if (capacity == slots.length) {
            return;
        }
        int n = Math.min(size, capacity);
        Object[] fresh = new Object[capacity];
        for (int i = 0; i < n; i++) {
            fresh[i] = slots[(head + size - n + i) % slots.length];
        }
        slots = fresh;
        capacityHint = capacity;
        head = 0;
        size = n;
    }

    synchronized int capacity() {
        return slots.length;
    }

    /** @return the capacity, without taking the lock (for a recording thread's cheap checks) */
    int capacityHint() {
        return capacityHint;
    }

    synchronized int size() {
        return size;
    }

    /** @return the sequence number of the newest entry, 0 if nothing was ever appended */
    synchronized long lastSequence() {
        return lastSequence;
    }

    @SuppressWarnings("unchecked")
    private List<E> copy(int offset, int n) {
        List<E> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            out.add((E) slots[(head + offset + i) % slots.length]);
        }
        return Collections.unmodifiableList(out);
    }

    private static int check(int capacity) {
        if (capacity < 1 || capacity > MAX_CAPACITY) {
            throw new IllegalArgumentException("capacity must be between 1 and " + MAX_CAPACITY + ", not " + capacity);
        }
        return capacity;
    }
}

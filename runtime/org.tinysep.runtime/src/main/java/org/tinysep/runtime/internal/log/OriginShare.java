package org.tinysep.runtime.internal.log;

import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.Predicate;

/**
 * A log's fair share per origin: the newest {@code perOrigin} entries of every origin, kept
 * beside the rotating files, so that a flood from some origins cannot rotate the last entries of the others out
 * of the history. Bounded: at most {@code maxOrigins} node origins ({@code node <address>}, which only the bus
 * radios write, for nodes within their {@code maxNodes}) and {@code maxOrigins} other origins (rejected senders'
 * addresses, drivers, devices), each with at most {@code perOrigin} entries. When a group is full, a new origin
 * replaces that group's least recently active one, so senders that are not nodes can never push a node out.
 * Thread-safe: the writer thread adds and saves, queries read.
 *
 * @param <E> the entry type
 */
final class OriginShare<E> {

    /** The entries of one origin and when (wall clock) the newest was added, for the retention. */
    private static final class Slot<E> {
        final ArrayDeque<E> entries = new ArrayDeque<>();
        Instant added;
    }

    private final Function<E, String> origin;
    private final int perOrigin;
    private final Map<String, Slot<E>> nodes;
    private final Map<String, Slot<E>> others;

    /**
     * @param origin     the entry's origin as written in the log
     * @param perOrigin  entries kept per origin (0: none)
     * @param maxOrigins origins kept per group (nodes, others)
     */
    OriginShare(Function<E, String> origin, int perOrigin, int maxOrigins) {
        this.origin = origin;
        this.perOrigin = perOrigin;
        this.nodes = lru(maxOrigins);
        this.others = lru(maxOrigins);
    }

    private static <E> Map<String, Slot<E>> lru(int max) {
        return new LinkedHashMap<>(16, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<String, Slot<E>> eldest) {
                return size() > max;
            }
        };
    }

    /**
     * The origin an entry is counted under: {@code node <address>} for a node's frames (whatever the socket
     * address after {@code via}), else the origin's first word without a {@code :port} (a rejected sender's
     * address counts once, whatever its port).
     */
    static String key(String origin) {
        String o = origin == null ? "" : origin;
        if (o.startsWith("node ")) {
            int end = o.indexOf(' ', 5);
            return end < 0 ? o : o.substring(0, end);
        }
        int space = o.indexOf(' ');
        int end = space < 0 ? o.length() : space;
        int digits = end;
        while (digits > 0 && o.charAt(digits - 1) >= '0' && o.charAt(digits - 1) <= '9') {
            digits--;
        }
        if (digits < end && digits > 0 && o.charAt(digits - 1) == ':') {
            end = digits - 1; // a ":port" suffix
        }
        // no regular expression per entry: the writer thread keys every event (issue 29; a compiled pattern and
        // its matcher per call were 40 % of what the event writer allocated under 1,000 frames/s)
        return end == o.length() ? o : o.substring(0, end);
    }

    /** Adds an entry written to the files at {@code now} (wall clock); drops its origin's oldest beyond the share. */
    synchronized void add(E entry, Instant now) {
        if (perOrigin == 0) {
            return;
        }
        String key = key(origin.apply(entry));
        Map<String, Slot<E>> group = key.startsWith("node ") ? nodes : others;
        Slot<E> slot = group.computeIfAbsent(key, k -> new Slot<>());
        slot.entries.addLast(entry);
        slot.added = now;
        while (slot.entries.size() > perOrigin) {
            slot.entries.removeFirst();
        }
    }

    /**
     * Forgets the origins whose newest entry was added before {@code cutoff} (the retention; null: none).
     *
     * @return whether any was forgotten
     */
    synchronized boolean expire(Instant cutoff) {
        boolean removed = false;
        for (Map<String, Slot<E>> group : List.of(nodes, others)) {
            for (Iterator<Slot<E>> it = group.values().iterator(); cutoff != null && it.hasNext();) {
                if (it.next().added.isBefore(cutoff)) {
                    it.remove();
                    removed = true;
                }
            }
        }
        return removed;
    }

    /** @return whether entries are kept at all ({@code perOrigin > 0}) */
    boolean enabled() {
        return perOrigin > 0;
    }

    /** @return every kept entry, in {@code sequence} order */
    synchronized List<E> all(Comparator<E> order) {
        List<E> out = new ArrayList<>();
        for (Map<String, Slot<E>> group : List.of(nodes, others)) {
            group.values().forEach(s -> out.addAll(s.entries));
        }
        out.sort(order);
        return out;
    }

    /** @return the kept entries matching {@code filter} that pass {@code older}, in {@code order} */
    List<E> matching(Predicate<E> filter, Predicate<E> older, Comparator<E> order) {
        List<E> out = new ArrayList<>();
        for (E e : all(order)) {
            if (older.test(e) && filter.test(e)) {
                out.add(e);
            }
        }
        return out;
    }

    /** @return how many entries are kept */
    synchronized int size() {
        int n = 0;
        for (Map<String, Slot<E>> group : List.of(nodes, others)) {
            for (Slot<E> s : group.values()) {
                n += s.entries.size();
            }
        }
        return n;
    }
}

package org.tinysep.web.api.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Predicate;

/**
 * Failure times per key within a sliding window, for {@link LoginLimiter}: at most {@code keep} times per key and
 * {@value #MAX_KEYS} keys (beyond that, keys whose failures have all passed the window go first, then the keys
 * {@code evictable} names).
 */
final class FailureCounts {

    static final int MAX_KEYS = 4096;

    private final Duration window;
    private final int keep;
    private final Map<String, Deque<Instant>> failures = new ConcurrentHashMap<>();

    FailureCounts(Duration window, int keep) {
        this.window = window;
        this.keep = keep;
    }

    void add(String key, Instant now, Predicate<String> evictable) {
        if (failures.size() >= MAX_KEYS) {
            failures.entrySet().removeIf(e -> count(e.getValue(), now) == 0);
            if (failures.size() >= MAX_KEYS) {
                failures.keySet().removeIf(evictable);
            }
        }
        Deque<Instant> d = failures.computeIfAbsent(key, k -> new ArrayDeque<>());
        synchronized (d) {
            d.addLast(now);
            while (d.size() > keep) {
                d.removeFirst();
            }
        }
    }

    /** @return the failures of {@code key} within the window before {@code now} */
    int count(String key, Instant now) {
        Deque<Instant> d = failures.get(key);
        return d == null ? 0 : count(d, now);
    }

    /** @return how long until fewer than {@code max} failures of {@code key} are within the window; zero if already */
    Duration waitBelow(String key, int max, Instant now) {
        Deque<Instant> d = failures.get(key);
        if (d == null) {
            return Duration.ZERO;
        }
        synchronized (d) {
            d.removeIf(t -> !t.plus(window).isAfter(now));
            if (d.size() < max) {
                return Duration.ZERO;
            }
            Instant oldestCounted = d.stream().skip(d.size() - max).findFirst().orElse(now);
            return Duration.between(now, oldestCounted.plus(window));
        }
    }

    /** @return how many keys starting with {@code prefix} have failures within the window */
    int keysWithFailures(String prefix, Instant now) {
        return (int) failures.entrySet().stream()
                .filter(e -> e.getKey().startsWith(prefix) && count(e.getValue(), now) > 0).count();
    }

    void forget(String key) {
        failures.remove(key);
    }

    private int count(Deque<Instant> d, Instant now) {
        synchronized (d) {
            d.removeIf(t -> !t.plus(window).isAfter(now));
            return d.size();
        }
    }
}

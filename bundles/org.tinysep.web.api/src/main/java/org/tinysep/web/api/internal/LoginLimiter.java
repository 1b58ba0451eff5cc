package org.tinysep.web.api.internal;

import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Rate limit on failed logins: after {@code maxFailures} failures within {@code window} from one client address
 * (and, against distributed guessing, after 4 × that many from all clients together) further attempts are
 * refused until the window has passed. A successful login clears its client's failures.
 */
public final class LoginLimiter {

    private static final String ALL = "*";
    private static final int MAX_CLIENTS = 1024;

    private final int maxFailures;
    private final Duration window;
    private final Clock clock;
    private final Map<String, Deque<Instant>> failures = new ConcurrentHashMap<>();

    public LoginLimiter(int maxFailures, Duration window, Clock clock) {
        this.maxFailures = Math.max(1, maxFailures);
        this.window = window;
        this.clock = clock;
    }

    /** @return how long {@code client} must wait before trying again; zero when it may try now */
    public Duration waitFor(String client) {
        Instant now = clock.instant();
        Duration own = wait(client, maxFailures, now);
        Duration all = wait(ALL, maxFailures * 4, now);
        return own.compareTo(all) >= 0 ? own : all;
    }

    /** Counts one failed login of {@code client}. */
    public void failed(String client) {
        Instant now = clock.instant();
        if (failures.size() > MAX_CLIENTS) {
            failures.keySet().removeIf(k -> !k.equals(ALL));
        }
        for (String key : new String[] {client, ALL}) {
            Deque<Instant> d = failures.computeIfAbsent(key, k -> new ArrayDeque<>());
            synchronized (d) {
                d.addLast(now);
                while (d.size() > maxFailures * 4) {
                    d.removeFirst();
                }
            }
        }
    }

    /** Forgets the failures of {@code client} after a successful login. */
    public void succeeded(String client) {
        failures.remove(client);
    }

    private Duration wait(String key, int max, Instant now) {
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
}

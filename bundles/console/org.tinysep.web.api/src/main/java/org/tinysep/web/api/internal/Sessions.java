package org.tinysep.web.api.internal;

import java.security.SecureRandom;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.Base64;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Logged-in sessions, in memory only (a restart logs everybody out). A session is known by a random 256-bit
 * token (the cookie) and carries its own random CSRF token; it ends after {@code idle} without a request.
 */
public final class Sessions {

    /** One logged-in user. */
    public record Session(String token, Role role, String csrf, Instant created) {
    }

    private static final SecureRandom RANDOM = new SecureRandom();
    private static final int MAX_SESSIONS = 64;

    private final Map<String, Entry> sessions = new ConcurrentHashMap<>();
    private final Duration idle;
    private final Clock clock;

    private static final class Entry {
        final Session session;
        volatile Instant lastUse;

        Entry(Session session, Instant lastUse) {
            this.session = session;
            this.lastUse = lastUse;
        }
    }

    public Sessions(Duration idle, Clock clock) {
        this.idle = idle;
        this.clock = clock;
    }

    /** Starts a session for {@code role}; the oldest sessions go when there are too many. */
    public Session open(Role role) {
        Instant now = clock.instant();
        expire(now);
        while (sessions.size() >= MAX_SESSIONS) {
            sessions.entrySet().stream().min((a, b) -> a.getValue().lastUse.compareTo(b.getValue().lastUse))
                    .ifPresent(oldest -> sessions.remove(oldest.getKey()));
        }
        Session s = new Session(random(), role, random(), now);
        sessions.put(s.token(), new Entry(s, now));
        return s;
    }

    /** @return the live session of {@code token} (and marks it used), if any */
    public Optional<Session> find(String token) {
        if (token == null || token.isEmpty()) {
            return Optional.empty();
        }
        Entry e = sessions.get(token);
        if (e == null) {
            return Optional.empty();
        }
        Instant now = clock.instant();
        if (e.lastUse.plus(idle).isBefore(now)) {
            sessions.remove(token);
            return Optional.empty();
        }
        e.lastUse = now;
        return Optional.of(e.session);
    }

    /**
     * @return whether the session of {@code token} is still alive (not logged out, ended by a password change, or
     *         idle too long), without counting this as a use: an open live stream does not keep its session alive
     */
    public boolean alive(String token) {
        Entry e = token == null ? null : sessions.get(token);
        return e != null && !e.lastUse.plus(idle).isBefore(clock.instant());
    }

    /** Ends the session of {@code token}. */
    public void close(String token) {
        if (token != null) {
            sessions.remove(token);
        }
    }

    /** Ends every session (e.g. on a password change or shutdown). */
    public void clear() {
        sessions.clear();
    }

    private void expire(Instant now) {
        sessions.values().removeIf(e -> e.lastUse.plus(idle).isBefore(now));
    }

    private static String random() {
        byte[] b = new byte[32];
        RANDOM.nextBytes(b);
        return Base64.getUrlEncoder().withoutPadding().encodeToString(b);
    }
}

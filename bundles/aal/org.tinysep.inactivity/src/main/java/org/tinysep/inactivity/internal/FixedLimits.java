package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.tinysep.inactivity.internal.learn.Amounts;
import org.tinysep.inactivity.internal.learn.Limit;
import org.tinysep.inactivity.internal.learn.Sighting;

/**
 * The THESIS detector's limits: the room's fixed limit, with its explanation ("fixed limit of 45 min for Bathroom
 * (detector THESIS)") made once per room name and fixed limit, not per activity (issue 29, item 1: the words were
 * built on the radio's delivery thread for every movement report, and only a reader needs them). Thread-safe.
 */
final class FixedLimits implements LimitPolicy {

    /** More room names than a home has (e.g. many unplaced devices): start afresh (bounded memory). */
    static final int MAX_ROOMS = 4_096;

    private final Map<String, Limit> byRoomName = new ConcurrentHashMap<>();

    @Override
    public Limit limitAfter(Sighting s, Duration fixed, Instant now) {
        Limit l = byRoomName.get(s.roomName());
        if (l != null && l.limit().equals(fixed)) {
            return l;
        }
        l = new Limit(fixed, false, words(s.roomName(), fixed));
        if (byRoomName.size() >= MAX_ROOMS) {
            byRoomName.clear();
        }
        byRoomName.put(s.roomName(), l); // a race makes the same words twice at worst (Limit is immutable)
        return l;
    }

    static String words(String roomName, Duration fixed) {
        return "fixed limit of " + Amounts.duration(fixed) + " for " + roomName + " (detector THESIS)";
    }
}

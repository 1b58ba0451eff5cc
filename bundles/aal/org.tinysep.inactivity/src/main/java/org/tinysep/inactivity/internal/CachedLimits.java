package org.tinysep.inactivity.internal;

import java.time.DayOfWeek;
import java.time.Duration;
import java.time.Instant;
import java.time.ZonedDateTime;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.Limit;
import org.tinysep.inactivity.internal.learn.QuietProfile;
import org.tinysep.inactivity.internal.learn.Sighting;

/**
 * The LEARNED detector's limits, computed once per room, hour, day type and state until the next learning (issue
 * 29, item 1: the limit and its explanation text were computed per activity, 28 % of the radio thread's Java time
 * at the thesis's load). Every activity is still learned from ({@link LearnedLimits#history()}); only the answer
 * is reused. What an answer depends on is the key: the room (UID, name, type), its fixed limit, the state (asleep,
 * seated), the activity's local hour and day type (weekday or weekend), and the learned profile, which the
 * learner replaces at each learning (once per local day, and when history was loaded): a new profile empties the
 * cache. So the work per activity does not grow with the history's length. Thread-safe.
 */
final class CachedLimits {

    /** More keys than a home has rooms × hours × states (e.g. many unplaced devices): start afresh. */
    static final int MAX_KEYS = 4_096;

    private record Key(String room, String roomName, String roomType, Duration fixed, boolean asleep,
            boolean seated, int hour, boolean weekend) {
    }

    /** The answers learned from one profile. */
    private record Answers(QuietProfile profile, Map<Key, Limit> limits) {
    }

    private final LearnedLimits limits;
    private final AtomicLong computed = new AtomicLong();
    private volatile Answers answers = new Answers(null, new ConcurrentHashMap<>());

    CachedLimits(LearnedLimits limits) {
        this.limits = limits;
    }

    /** As {@link LearnedLimits#limitAfter}, reusing the answer for the same key since the last learning. */
    Limit limitAfter(Sighting s, Duration fixed, Instant now) {
        limits.history().add(s); // every activity is learned from, first, as LearnedLimits does
        QuietProfile profile = limits.history().profile(now); // learns anew when due (a new day, history loaded)
        Answers a = answers;
        if (a.profile() != profile || a.limits().size() > MAX_KEYS) {
            a = new Answers(profile, new ConcurrentHashMap<>());
            answers = a;
        }
        ZonedDateTime t = s.at().atZone(limits.history().sleep().zone());
        boolean asleep = limits.history().sleep().asleep(s);
        DayOfWeek d = t.getDayOfWeek();
        Key key = new Key(s.room(), s.roomName(), s.roomType(), fixed, asleep, s.seated() && !asleep, t.getHour(),
                d == DayOfWeek.SATURDAY || d == DayOfWeek.SUNDAY);
        Limit cached = a.limits().get(key);
        if (cached != null) {
            return cached;
        }
        computed.incrementAndGet();
        Limit l = limits.limitAfter(s, fixed, now); // adds s again: it is the newest sighting, so kept once
        a.limits().put(key, l);
        return l;
    }

    /** @return how many times a limit (and its explanation) was computed rather than reused */
    long computed() {
        return computed.get();
    }

    LearnedLimits learned() {
        return limits;
    }
}

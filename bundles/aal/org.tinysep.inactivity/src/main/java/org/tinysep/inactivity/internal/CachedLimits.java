package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.zone.ZoneOffsetTransition;
import java.time.zone.ZoneRules;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.Limit;
import org.tinysep.inactivity.internal.learn.QuietProfile;
import org.tinysep.inactivity.internal.learn.Sighting;
import org.tinysep.inactivity.internal.learn.SleepRule;

/**
 * The LEARNED detector's limits, computed once per room, hour, day type and state until the next learning (issue
 * 29, item 1: the limit and its explanation text were computed per activity, 28 % of the radio thread's Java time
 * at the thesis's load). Every activity is still learned from ({@link LearnedLimits#history()}); only the answer
 * is reused. What an answer depends on is the key: the room (UID, name, type), its fixed limit, the state (asleep,
 * seated, getting up), the activity's local hour and day type (weekday or weekend), and the learned profile, which the
 * learner replaces at each learning (once per local day, and when history was loaded): a new profile empties the
 * cache. So the work per activity does not grow with the history's length. Thread-safe.
 *
 * <p>A known answer is found without allocating or hashing a composite key (that was 15 % of the radio thread):
 * the room's UID and name (strings whose hash the JDK keeps, since they are the same objects activity after
 * activity) lead to the room's {@link Slots}, and the state, day type and hour index its array of answers.
 */
final class CachedLimits {

    /** More rooms (by UID and name) than a home has (e.g. many unplaced devices): start afresh. */
    static final int MAX_KEYS = 4_096;
    /** Answers per room: getting up × asleep × seated × weekend × 24 hours. */
    private static final int PER_ROOM = 2 * 2 * 2 * 2 * 24;

    /** In bed × up from bed × 24 local hours: whether a sighting there is sleep (0 not yet asked, 1 no, 2 yes). */
    private static final int SLEEP_KEYS = 2 * 2 * 24;

    /**
     * One room's answers, valid while its type and fixed limit stay these; and whether a sighting in it is sleep,
     * which depends only on the room's type, the bed mat's word and the local hour ({@link SleepRule#asleep}):
     * asked once per hour and bed state, not per activity (it reads the hour through a new zoned date-time and
     * lower-cases the room's type each time).
     */
    private record Slots(String roomType, Duration fixed, Limit[] answers, byte[] asleep) {

        boolean asleep(Sighting s, int hour, SleepRule rule) {
            int k = ((s.inBed() ? 1 : 0) * 2 + (s.upFromBed() ? 1 : 0)) * 24 + hour;
            byte known = asleep[k];
            if (known == 0) {
                known = rule.asleep(s) ? (byte) 2 : (byte) 1;
                asleep[k] = known; // a race asks twice at worst: the same answer
            }
            return known == 2;
        }
    }

    /** The answers learned from one profile: room UID → room name → slots. */
    private record Answers(QuietProfile profile, Map<String, Map<String, Slots>> rooms, AtomicLong size) {
    }

    private final LearnedLimits limits;
    private final AtomicLong computed = new AtomicLong();
    private volatile Answers answers = fresh(null);
    private volatile Zone zone = new Zone(null, null, 0, 0, 0);

    /**
     * The home's zone, its rules (a fixed offset's rules are a new object per call in Java 17), and its offset from
     * UTC, valid from {@code from} until {@code until} (epoch seconds, exclusive: the zone's next transition). A
     * region's offset asked of its rules per activity cost a local date and a boxed year per question (issue 29,
     * item 1); it changes twice a year.
     */
    private record Zone(ZoneId id, ZoneRules rules, long from, long until, int offset) {
    }

    CachedLimits(LearnedLimits limits) {
        this.limits = limits;
    }

    private static Answers fresh(QuietProfile profile) {
        return new Answers(profile, new ConcurrentHashMap<>(), new AtomicLong());
    }

    /** As {@link LearnedLimits#limitAfter}, reusing the answer for the same key since the last learning. */
    Limit limitAfter(Sighting s, Duration fixed, Instant now) {
        limits.history().add(s); // every activity is learned from, first, as LearnedLimits does
        limits.history().fixedLimit(s.room(), fixed); // and its room's fixed limit known to the check
        QuietProfile profile = limits.history().profile(now); // learns anew when due (a new day, history loaded)
        Answers a = answers;
        if (a.profile() != profile || a.size().get() > MAX_KEYS) {
            a = fresh(profile);
            answers = a;
        }
        SleepRule rule = limits.history().sleep();
        Slots room = slots(a, s, fixed);
        long local = localSeconds(s.at(), rule.zone());
        boolean asleep = room.asleep(s, hourOf(local), rule);
        Limit[] slots = room.answers();
        int i = index(local, asleep, s.seated() && !asleep) + (s.upFromBed() && !asleep ? PER_ROOM / 2 : 0);
        Limit cached = slots[i];
        if (cached != null) {
            return cached;
        }
        computed.incrementAndGet();
        Limit l = limits.limitAfter(s, fixed, now); // adds s again: it is the newest sighting, so kept once
        slots[i] = l; // a race computes the same answer twice at worst (Limit is immutable)
        return l;
    }

    private static Slots slots(Answers a, Sighting s, Duration fixed) {
        Map<String, Slots> byName = a.rooms().get(s.room());
        if (byName == null) {
            byName = a.rooms().computeIfAbsent(s.room(), r -> new ConcurrentHashMap<>());
        }
        Slots slots = byName.get(s.roomName());
        if (slots == null || !slots.roomType().equals(s.roomType()) || !slots.fixed().equals(fixed)) {
            slots = new Slots(s.roomType(), fixed, new Limit[PER_ROOM], new byte[SLEEP_KEYS]);
            byName.put(s.roomName(), slots);
            a.size().incrementAndGet();
        }
        return slots;
    }

    /** @return {@code at} as seconds of the local time line of {@code id} (the epoch's local midnight is 0) */
    long localSeconds(Instant at, ZoneId id) {
        Zone z = zone;
        long sec = at.getEpochSecond();
        if (z.id() != id || sec < z.from() || sec >= z.until()) {
            ZoneRules rules = z.id() == id ? z.rules() : id.getRules();
            ZoneOffsetTransition next = rules.nextTransition(at);
            z = new Zone(id, rules, sec, next == null ? Long.MAX_VALUE : next.toEpochSecond(),
                    rules.getOffset(at).getTotalSeconds());
            zone = z;
        }
        return sec + z.offset();
    }

    /** @return the answer's place: the state, weekday or weekend, and the local hour of {@code at} */
    static int index(Instant at, ZoneRules zone, boolean asleep, boolean seated) {
        return index(localSeconds(at, zone), asleep, seated);
    }

    /** @return {@code at} as seconds of the local time line (the epoch's local midnight is 0) */
    private static long localSeconds(Instant at, ZoneRules zone) {
        return at.getEpochSecond() + zone.getOffset(at).getTotalSeconds();
    }

    private static int hourOf(long local) {
        return (int) (Math.floorMod(local, 86_400L) / 3_600);
    }

    private static int index(long local, boolean asleep, boolean seated) {
        int hour = hourOf(local);
        int dayOfWeek = (int) Math.floorMod(Math.floorDiv(local, 86_400L) + 3, 7L); // day 0 was a Thursday; 0 = Monday
        int weekend = dayOfWeek >= 5 ? 1 : 0;
        return (((asleep ? 1 : 0) * 2 + (seated ? 1 : 0)) * 2 + weekend) * 24 + hour;
    }

    /** @return how many times a limit (and its explanation) was computed rather than reused */
    long computed() {
        return computed.get();
    }

    LearnedLimits learned() {
        return limits;
    }
}

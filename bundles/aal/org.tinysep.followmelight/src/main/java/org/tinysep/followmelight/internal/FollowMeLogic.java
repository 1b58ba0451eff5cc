package org.tinysep.followmelight.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tinysep.api.service.Occupancy;

/**
 * The Follow Me Light algorithm (thesis 4.4.4.2; rules in the bundle README). Pure logic on rooms with explicit
 * times, so it runs in virtual time and is tested without sleeping.
 * <ul>
 * <li>Motion in a room while the flat is OCCUPIED lights the room (once) and restarts its grace period.</li>
 * <li>A lit room without motion for the grace period goes dark. Nobody can count persons, so this is the rule for
 * one person and for several alike: a room where someone still moves stays lit.</li>
 * <li>Pet motion counts like person motion, but only while the flat is OCCUPIED (a pet alone does nothing).</li>
 * <li>Person motion seen while the flat is not (yet) OCCUPIED is kept for {@link #ARRIVAL_WINDOW}: Flat
 * Occupancy may hear the same motion after us and only then say OCCUPIED.</li>
 * <li>UNOCCUPIED: every lit room goes dark; nothing happens until the flat is OCCUPIED again.</li>
 * <li>A clock that went back (virtual time, then real time): at the next tick a room's motion time later than
 * {@code now} is taken as {@code now}, so the room goes dark after the grace period on the new clock and fresh
 * motion counts again.</li>
 * </ul>
 * Not thread-safe: the device serialises calls.
 */
final class FollowMeLogic {

    static final Duration ARRIVAL_WINDOW = Duration.ofSeconds(5);
    /** Times this much later than {@code now} are threads racing, not a clock that went back. */
    static final Duration CLOCK_SLACK = Duration.ofSeconds(2);

    private final Duration grace;
    private final Map<String, Instant> lit = new LinkedHashMap<>();
    private final Map<String, Instant> waiting = new LinkedHashMap<>();
    private Occupancy occupancy = Occupancy.UNKNOWN;

    FollowMeLogic(Duration grace) {
        if (grace.isNegative() || grace.isZero()) {
            throw new IllegalArgumentException("grace must be positive, was " + grace);
        }
        this.grace = grace;
    }

    /** A person moved in {@code roomUid}. */
    List<Command> personMotion(String roomUid, Instant at) {
        if (occupancy != Occupancy.OCCUPIED) {
            waiting.put(roomUid, at);
            return List.of();
        }
        return motion(roomUid, at, "motion");
    }

    /** The pet moved in {@code roomUid}: counts only while someone is home. */
    List<Command> petMotion(String roomUid, Instant at) {
        return occupancy == Occupancy.OCCUPIED ? motion(roomUid, at, "pet motion") : List.of();
    }

    private List<Command> motion(String roomUid, Instant at, String what) {
        Instant before = lit.get(roomUid);
        if (before != null && before.isAfter(at)) {
            return List.of(); // a late report: the room's newer motion stands (a clock step: re-based by tick)
        }
        lit.put(roomUid, at);
        return before == null ? List.of(new Command(roomUid, true, what)) : List.of();
    }

    /** The flat's occupancy is {@code next} since {@code at}. */
    List<Command> occupancy(Occupancy next, Instant at) {
        Occupancy was = occupancy;
        occupancy = next;
        List<Command> out = new ArrayList<>();
        if (next == Occupancy.OCCUPIED && was != Occupancy.OCCUPIED) {
            Instant from = at.minus(ARRIVAL_WINDOW);
            waiting.forEach((room, t) -> {
                if (!t.isBefore(from)) {
                    out.addAll(motion(room, t, "motion on arrival"));
                }
            });
        } else if (next != Occupancy.OCCUPIED) {
            lit.keySet().forEach(room -> out.add(new Command(room, false, "flat " + next.name().toLowerCase())));
            lit.clear();
        }
        waiting.clear();
        return out;
    }

    /** Time passed: rooms quiet for the grace period go dark. */
    List<Command> tick(Instant now) {
        Instant limit = now.plus(CLOCK_SLACK);
        lit.replaceAll((room, t) -> t.isAfter(limit) ? now : t); // the clock went back: count from now
        waiting.replaceAll((room, t) -> t.isAfter(limit) ? now : t);
        List<Command> out = new ArrayList<>();
        for (Iterator<Map.Entry<String, Instant>> it = lit.entrySet().iterator(); it.hasNext();) {
            Map.Entry<String, Instant> e = it.next();
            if (!now.isBefore(e.getValue().plus(grace))) {
                it.remove();
                out.add(new Command(e.getKey(), false, "no motion for " + grace.toSeconds() + " s"));
            }
        }
        waiting.values().removeIf(t -> t.isBefore(now.minus(ARRIVAL_WINDOW)));
        return out;
    }

    /**
     * @return when {@link #tick} next has something to do: the end of the first lit room's grace period; null while
     *         no room is lit (motion waiting for an arrival is only forgotten, it needs no tick of its own)
     */
    Instant nextDue() {
        Instant first = null;
        for (Instant t : lit.values()) {
            Instant end = t.plus(grace);
            if (first == null || end.isBefore(first)) {
                first = end;
            }
        }
        return first;
    }

    Set<String> litRooms() {
        return Set.copyOf(lit.keySet());
    }

    Occupancy occupancy() {
        return occupancy;
    }
}

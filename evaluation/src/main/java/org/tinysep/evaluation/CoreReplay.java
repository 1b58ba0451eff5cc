package org.tinysep.evaluation;

import java.time.Duration;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Predicate;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.LearningSettings;
import org.tinysep.inactivity.internal.learn.Limit;
import org.tinysep.inactivity.internal.learn.Residents;
import org.tinysep.inactivity.internal.learn.Sighting;
import org.tinysep.inactivity.internal.learn.SleepRule;
import org.tinysep.simulator.replay.NodeSpec;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * The detector core without the platform, for analysis and sweeps only (published figures come from the platform
 * run): the recording's events become activities as Inactivity Recognition sees them (motion ON, every door and
 * window change), Flat Occupancy is approximated (outer door closed and no indoor activity for 600 s: empty), and
 * the limit of each quiet period comes from the learned detector's own classes ({@code LearnedLimits}) or the
 * thesis's fixed limits. An alert is raised when a quiet period outlasts its limit while the flat counts as
 * occupied.
 */
final class CoreReplay {

    static final Duration LEAVE = Duration.ofSeconds(600);
    static final Duration GRACE = Duration.ofSeconds(10);
    /** {@code -Dseated=false}: a seat mat turning ON is not told apart (session 20's detector), for comparison. */
    static final boolean SEATED = !"false".equals(System.getProperty("seated"));

    /** {@code -DupFromBed=false}: a bed mat turning OFF does not end sleep, to compare the detector without it. */
    static final boolean UP_FROM_BED = !"false".equals(System.getProperty("upFromBed"));

    /**
     * {@code -DdeviceOff=true}: a flush or appliance turning OFF counts as activity also when the last activity was
     * in another room (the detector before issue 28's session 32), for comparison.
     */
    static final boolean FINISHED_BY_ITSELF = !Boolean.getBoolean("deviceOff");

    /**
     * {@code -Drepeats=true}: a door, window or mat recorded in the state it already had (Ordonez B: seat ON 12:41:45,
     * seat ON again 12:56:27, no OFF between), and its first report in the recording (B: seat ON at 21:14:21, the
     * recording's first event, was learned as a 3 h 07 evening sit), count as activity, as in the core before session
     * 33. The platform's devices tell changes only ({@code SensorDevice}: "listeners hear changes only") and their
     * first report is no activity, so by default neither is.
     */
    static final boolean REPEATS_DROPPED = !Boolean.getBoolean("repeats");

    /**
     * The home's residents as Inactivity Recognition's {@code residents} setting: the home's own ({@link Home#residents},
     * 0: recognised from the history), or {@code -Dresidents=<n>} for an experiment (e.g. the rules of a shared home on
     * a one-resident recording).
     */
    private int residents() {
        return Integer.getInteger("residents", home.residents());
    }

    /**
     * An activity as the detector sees it.
     *
     * @param type the node's type: a bed mat (PRESENCE_BED) turning ON is "in bed", OFF "getting up"; a seat mat
     *             turning ON "sat down" — by the type, as the platform's {@code ActivityFactory} does (by its name,
     *             session 33 found, "Bedroom door (PIR)" was a bed: every bedroom movement was sleep, by day too)
     * @param resting unless the home declares 1 resident, the mat ON in this room when the activity happened
     *             (PRESENCE_BED or PRESENCE_SEAT; in a home of several the learn package's {@code Residents} reads the
     *             activity as a resting person's), else null
     */
    record Act(Instant at, String room, String what, boolean outerClose, boolean outerDoor, AmicaNodeType type,
            AmicaNodeType resting) {
        /** An activity of a node that is no bed or seat mat. */
        Act(Instant at, String room, String what, boolean outerClose, boolean outerDoor) {
            this(at, room, what, outerClose, outerDoor, AmicaNodeType.MOVEMENT);
        }

        /** An activity in a room where no mat is ON, or of a home of one resident. */
        Act(Instant at, String room, String what, boolean outerClose, boolean outerDoor, AmicaNodeType type) {
            this(at, room, what, outerClose, outerDoor, type, null);
        }

        /** @return the sighting as a home of several residents reads it */
        Sighting sighting() {
            return sighting(true);
        }

        /** @param several whether the home is one of several residents now (declared, or seen in the history) */
        Sighting sighting(boolean several) {
            boolean on = what.endsWith(" on");
            boolean bed = type == AmicaNodeType.PRESENCE_BED;
            Sighting s = new Sighting(at, System.getProperty("cause") != null ? room + "|" + what : room, room, room,
                    on && bed, on && type == AmicaNodeType.PRESENCE_SEAT && SEATED, !on && bed && UP_FROM_BED);
            return resting == null || !several ? s
                    : Residents.read(s, resting == AmicaNodeType.PRESENCE_BED, resting == AmicaNodeType.PRESENCE_SEAT);
        }
    }

    /** A raised alert: when, the quiet period's room and start, its limit and why. */
    record Alert(Instant at, Act after, Duration limit, String why) {
    }

    private final Home home;
    private final boolean learned;
    private final Map<String, NodeSpec> nodes = new HashMap<>();

    CoreReplay(Home home, boolean learned) {
        this.home = home;
        this.learned = learned;
        home.nodes().forEach(n -> nodes.put(n.sensor(), n));
    }

    static Instant at(LocalDateTime t) {
        return t.toInstant(ZoneOffset.UTC);
    }

    /** @return the events that are activities, in time order */
    List<Act> acts(List<SensorEvent> events) {
        List<Act> out = new ArrayList<>();
        Map<String, Boolean> state = events.isEmpty() ? new HashMap<>() : stateBefore(events.get(0).time());
        Residents residents = new Residents(residents());
        state.forEach((sensor, on) -> mat(residents, nodes.get(sensor), on));
        for (SensorEvent e : events) {
            NodeSpec n = nodes.get(e.sensor());
            if (n == null || (n.isMotion() && !e.on())) {
                continue;
            }
            mat(residents, n, e.on()); // as the platform's ActivityFactory: every report of a mat, its first too
            Boolean before = state.put(e.sensor(), e.on());
            if (!n.isMotion() && REPEATS_DROPPED && (before == null || before == e.on())) {
                // the recording's first report of a contact or mat is its resting state (the platform's devices say
                // "first", ActivityFactory ignores it); the same state again (the recording lost the change between)
                // is no change: the devices tell changes only
                continue;
            }
            if (FINISHED_BY_ITSELF && !e.on() && !out.isEmpty() && isDevice(n)
                    && !out.get(out.size() - 1).room().equals(n.room())) {
                continue; // the device finishing by itself: the person was last seen elsewhere (ActivityFactory)
            }
            boolean outer = "OUTER".equals(n.doorKind());
            Act a = new Act(at(e.time()), n.room(), n.name() + (e.on() ? " on" : " off"), outer && !e.on(), outer,
                    n.type());
            Sighting read = residents.resting(a.sighting()); // several or not: asked when played (limit)
            out.add(read.equals(a.sighting()) ? a : new Act(a.at(), a.room(), a.what(), a.outerClose(), a.outerDoor(),
                    a.type(), read.inBed() ? AmicaNodeType.PRESENCE_BED : AmicaNodeType.PRESENCE_SEAT));
        }
        return out;
    }

    /** Tells {@code residents} a bed or seat mat's state (other nodes: nothing). */
    private static void mat(Residents residents, NodeSpec n, boolean on) {
        if (n != null && (n.type() == AmicaNodeType.PRESENCE_BED || n.type() == AmicaNodeType.PRESENCE_SEAT)) {
            residents.mat(n.sensor(), n.room(), n.type() == AmicaNodeType.PRESENCE_BED, on);
        }
    }

    /**
     * The state of every sensor just before {@code t}, from the whole recording: a stretch replayed later (the test
     * half, a window) starts with the contacts' state as the platform's does ({@code StateReports}).
     */
    private Map<String, Boolean> stateBefore(LocalDateTime t) {
        Map<String, Boolean> state = new HashMap<>();
        for (SensorEvent e : home.events()) {
            if (!e.time().isBefore(t)) {
                break;
            }
            state.put(e.sensor(), e.on());
        }
        return state;
    }

    /** A flush or an appliance: its OFF can be the device finishing by itself. */
    static boolean isDevice(NodeSpec n) {
        return n.type() == AmicaNodeType.PRESENCE_FLUSH || n.type() == AmicaNodeType.PRESENCE_APPLIANCE;
    }

    static Duration fixed(String roomType) {
        return switch (roomType.toLowerCase(Locale.ROOT)) {
        case "bathroom" -> Duration.ofMinutes(45);
        case "kitchen" -> Duration.ofMinutes(90);
        case "living room" -> Duration.ofMinutes(180);
        case "bedroom" -> Duration.ofMinutes(600);
        case "hall" -> Duration.ofMinutes(30);
        default -> Duration.ofMinutes(120);
        };
    }

    LearnedLimits newLimits() {
        SleepRule sleep = new SleepRule(21, 7, ZoneOffset.UTC);
        return new LearnedLimits(new HistoryLearner(ZoneOffset.UTC, sleep, settings().withResidents(residents())));
    }

    Limit limit(LearnedLimits l, Act a) {
        Duration f = fixed(a.room());
        if (!learned) {
            return new Limit(f, false, "fixed");
        }
        Sighting raw = a.sighting(false);
        Sighting read = l.residents().several() && a.resting() != null ? a.sighting(true) : raw;
        return l.residents().explain(raw, read, l.limitAfter(read, f, a.at()));
    }

    /**
     * Plays {@code acts}, learning from every one (as the live detector does), and returns the alerts raised while
     * {@code judged} holds for the alert time.
     */
    List<Alert> play(LearnedLimits l, List<Act> acts, Predicate<Instant> judged) {
        List<Alert> alerts = new ArrayList<>();
        Instant occupiedSince = acts.isEmpty() ? Instant.MIN : acts.get(0).at();
        Instant[] empties = emptiesAfter(acts);
        for (int i = 0; i < acts.size(); i++) {
            Act a = acts.get(i);
            Limit lim = limit(l, a);
            Instant next = i + 1 < acts.size() ? acts.get(i + 1).at() : null;
            if (empties[i] != null) {
                l.history().occupancy(true, empties[i]);
                if (next != null) {
                    l.history().occupancy(false, next);
                    occupiedSince = next;
                }
                continue; // not watching until the next activity
            }
            Instant from = a.at().isAfter(occupiedSince) ? a.at() : occupiedSince;
            Instant due = from.plus(lim.limit());
            if ((next == null || next.isAfter(due)) && judged.test(due)) {
                alerts.add(new Alert(due, a, lim.limit(), lim.explanation()));
            }
        }
        return alerts;
    }

    /**
     * Flat Occupancy, approximated: the flat empties when the outer door closed and the leave check ({@link #LEAVE})
     * runs out before the next indoor activity; the next activity (any) makes it occupied again.
     *
     * @return per activity, when the flat became empty after it (before the next one), or null
     */
    static Instant[] emptiesAfter(List<Act> acts) {
        Instant[] out = new Instant[acts.size()];
        Instant leaveDeadline = null;
        Instant lastClose = null;
        for (int i = 0; i < acts.size(); i++) {
            Act a = acts.get(i);
            if (a.outerClose()) {
                lastClose = a.at();
                leaveDeadline = a.at().plus(LEAVE);
            }
            Instant next = i + 1 < acts.size() ? acts.get(i + 1).at() : null;
            boolean leaves = leaveDeadline != null && (next == null || next.isAfter(leaveDeadline))
                    && !a.at().isAfter(leaveDeadline);
            if (!a.outerDoor() && lastClose != null && a.at().isAfter(lastClose.plus(GRACE))) {
                leaveDeadline = null;
            }
            if (leaves && leaveDeadline != null) {
                out[i] = leaveDeadline;
                leaveDeadline = null;
            }
        }
        return out;
    }

    /**
     * Blind time: whether monitoring is blind at {@code t} — the flat counts as empty then, so Inactivity
     * Recognition is not watching and a collapse at {@code t} cannot be found.
     *
     * @param acts what the detector saw, in time order (later activities are ignored)
     */
    static boolean blindAt(List<Act> acts, Instant t) {
        List<Act> upTo = acts.stream().filter(a -> a.at().isBefore(t)).toList();
        if (upTo.isEmpty()) {
            return false;
        }
        Instant[] empties = emptiesAfter(upTo);
        Instant last = empties[empties.length - 1];
        return last != null && !t.isBefore(last);
    }

    /** @return the alert due after the last activity before a collapse (history learned first), or null if none */
    Alert collapse(List<Act> history, List<Act> before, LocalDateTime c) {
        LearnedLimits l = newLimits();
        play(l, history, t -> false);
        List<Alert> a = play(l, before, t -> true);
        Act last = before.get(before.size() - 1);
        Alert lastAlert = a.isEmpty() ? null : a.get(a.size() - 1);
        // raised before or after the collapse (the caller judges); none: the flat counted as empty
        return lastAlert != null && lastAlert.after().equals(last) ? lastAlert : null;
    }

    /**
     * The defaults, or a sweep's: {@code -Dfloor=<minutes> -Dmargin=<x> -Dpad=<minutes> -DminDays=<n>
     * -DminPeriods=<n>} (the last: {@code learnMinPeriodsToShorten}).
     */
    private static LearningSettings settings() {
        LearningSettings d = LearningSettings.defaults();
        return new LearningSettings(Integer.getInteger("minDays", d.minDays()), d.historyDays(),
                Double.parseDouble(System.getProperty("margin", Double.toString(d.margin()))),
                java.time.Duration.ofMinutes(Long.getLong("pad", d.pad().toMinutes())),
                java.time.Duration.ofMinutes(Long.getLong("floor", d.floor().toMinutes())), d.ceiling(),
                d.halfWindow(), Integer.getInteger("minPeriods", d.minPeriodsToShorten()));
    }
}

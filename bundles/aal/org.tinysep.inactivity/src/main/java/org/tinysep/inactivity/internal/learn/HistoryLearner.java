package org.tinysep.inactivity.internal.learn;

import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneId;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;

/**
 * Keeps the home's recent history (sightings and the times the flat was empty, from the event log at start and
 * live afterwards) and learns a {@link QuietProfile} from it, anew once per local day (and whenever history was
 * loaded). Sightings in the same room less than {@link #MERGE} apart are kept as one (the later), so a motion
 * sensor reporting every 2 s does not fill memory; that changes no quiet period longer than that. Thread-safe.
 */
public final class HistoryLearner {

    static final Duration MERGE = Duration.ofSeconds(60);

    private final ZoneId zone;
    private final SleepRule sleep;
    private final LearningSettings settings;
    private final Residents residents;
    private final List<Sighting> sightings = new ArrayList<>();
    private final List<QuietGaps.Away> away = new ArrayList<>();
    private Instant awaySince;
    private QuietProfile profile;
    private LocalDate builtFor;
    /** The local day {@link #builtFor} as instants [from, until): a question within it needs no date arithmetic. */
    private Instant dayFrom = Instant.MAX;
    private Instant dayUntil = Instant.MIN;
    private boolean dirty = true;
    /** Whether {@link #residents} was told what the history shows since it was last loaded. */
    private boolean residentsFound;
    private volatile Function<String, String> roomTypes = room -> "";
    /** Each room's fixed limit as last asked with (the day-by-day margin check compares with them). */
    private final Map<String, Duration> fixedLimits = new ConcurrentHashMap<>();

    public HistoryLearner(ZoneId zone, SleepRule sleep, LearningSettings settings) {
        this.zone = zone;
        this.sleep = sleep;
        this.settings = settings;
        this.residents = new Residents(settings.residents());
    }

    /** Something happened (live or from the log). */
    public synchronized void add(Sighting s) {
        if (!sightings.isEmpty()) {
            Sighting last = sightings.get(sightings.size() - 1);
            if (last.room().equals(s.room()) && last.inBed() == s.inBed() && last.seated() == s.seated()
                    && last.upFromBed() == s.upFromBed()
                    && !s.at().isBefore(last.at()) && withinMerge(last.at(), s.at())) {
                sightings.set(sightings.size() - 1, s);
                return;
            }
            // an older sighting (a frame replayed late, e.g. by a driver's handover) is sorted in at the next daily
            // learning, like every sighting of today: it does not make the profile learn anew now (that
            // would rebuild the whole profile once per replayed frame); history read from the log calls loaded()
        }
        sightings.add(s);
    }

    /** The flat became empty ({@code empty}) or occupied again at {@code at}. */
    public synchronized void occupancy(boolean empty, Instant at) {
        if (empty && awaySince == null) {
            awaySince = at;
        } else if (!empty && awaySince != null) {
            if (at.isAfter(awaySince)) {
                away.add(new QuietGaps.Away(awaySince, at));
            }
            awaySince = null;
        }
    }

    /**
     * A room's fixed limit, as the detector asks with it: the check of the margin ({@link MarginCheck}) counts the
     * alarms the fixed limits would have raised, at the next learning, in the rooms whose fixed limit it knows by
     * then (after a start, the rooms with activity since; it needs {@code minDays} days of history in any case).
     */
    public void fixedLimit(String room, Duration fixed) {
        if (!fixed.equals(fixedLimits.get(room))) { // asked per activity: a write only when it changes
            fixedLimits.put(room, fixed);
        }
    }

    /** History was loaded from the log: learn anew at the next question. */
    public synchronized void loaded() {
        dirty = true;
        residentsFound = false;
    }

    /** @return whether {@code later} is less than {@link #MERGE} after {@code earlier} (no Duration per sighting) */
    static boolean withinMerge(Instant earlier, Instant later) {
        long seconds = later.getEpochSecond() - earlier.getEpochSecond();
        if (later.getNano() < earlier.getNano()) {
            seconds--; // borrow: the nanoseconds part of the difference is then positive
        }
        return seconds < MERGE.getSeconds();
    }

    /**
     * @return the profile learned from the history up to {@code now} (at most a day old); asked per activity, so a
     *         question within the local day it was built for is answered without date arithmetic (issue 29: the
     *         zoned date per question was a tenth of Inactivity Recognition's time per movement report)
     */
    public synchronized QuietProfile profile(Instant now) {
        if (profile != null && !dirty && !now.isBefore(dayFrom) && now.isBefore(dayUntil)) {
            return profile;
        }
        LocalDate today = now.atZone(zone).toLocalDate();
        if (profile == null || dirty || !today.equals(builtFor)) {
            Instant oldest = now.minus(Duration.ofDays(settings.historyDays()));
            sightings.sort(Comparator.comparing(Sighting::at));
            sightings.removeIf(s -> s.at().isBefore(oldest));
            away.sort(Comparator.comparing(QuietGaps.Away::from));
            away.removeIf(a -> a.to().isBefore(oldest));
            List<QuietGaps.Away> empty = new ArrayList<>(away);
            if (awaySince != null) {
                empty.add(new QuietGaps.Away(awaySince, now));
            }
            List<Sighting> typed = sightings.stream().map(this::typed).toList();
            List<Gap> gaps = QuietGaps.of(typed, empty, sleep);
            if (residents.fromHistory()) {
                residents.found(TwoAtOnce.of(typed, zone));
            }
            residentsFound = true;
            LearningSettings home = settings.withResidents(residents.several() ? Math.max(2, settings.residents()) : 1);
            MarginCheck.Result check = MarginCheck.choose(gaps, zone, home, fixedLimits::get);
            profile = new QuietProfile(gaps, zone, home.withMargin(check.margin()), check.words());
            builtFor = today;
            dayFrom = today.atStartOfDay(zone).toInstant();
            dayUntil = today.plusDays(1).atStartOfDay(zone).toInstant();
            dirty = false;
        }
        return profile;
    }

    /** Room types for sightings that came without one (read from the log before the house plan was known). */
    public void roomTypes(Function<String, String> types) {
        roomTypes = types;
    }

    private Sighting typed(Sighting s) {
        if (!s.roomType().isEmpty() || s.inBed()) {
            return s;
        }
        String type = roomTypes.apply(s.room());
        return type == null || type.isEmpty() ? s : new Sighting(s.at(), s.room(), s.roomName(), type, false, s.seated(),
                s.upFromBed());
    }

    /**
     * What the learner remembers, for its own file beside the rotating event log.
     *
     * @param sightings the history, in time order
     * @param away      the times the flat was empty
     * @param awaySince since when the flat is empty now, or null
     */
    public record Memory(List<Sighting> sightings, List<QuietGaps.Away> away, Instant awaySince) {
        public Memory {
            sightings = List.copyOf(sightings);
            away = List.copyOf(away);
        }
    }

    /** @return a copy of what it remembers */
    public synchronized Memory memory() {
        sightings.sort(Comparator.comparing(Sighting::at));
        return new Memory(sightings, away, awaySince);
    }

    /** Adds what a saved memory held (at start, before the event log fills what it lacks); learns anew. */
    public synchronized void remember(Memory m) {
        sightings.addAll(m.sightings());
        away.addAll(m.away());
        if (awaySince == null) {
            awaySince = m.awaySince();
        }
        dirty = true;
        residentsFound = false;
    }

    public synchronized int size() {
        return sightings.size();
    }

    public SleepRule sleep() {
        return sleep;
    }

    public LearningSettings settings() {
        return settings;
    }

    /**
     * @return the home's residents: declared in the settings, or ({@code residents} 0) recognised from this history
     *         at every learning ({@link TwoAtOnce}); the profile's settings carry the count the rules use (1, or 2
     *         and more)
     */
    public synchronized Residents residents() {
        if (!residentsFound && residents.fromHistory()) { // before the first learning (after a start): now
            List<Sighting> sorted = new ArrayList<>(sightings);
            sorted.sort(Comparator.comparing(Sighting::at));
            residents.found(TwoAtOnce.of(sorted, zone));
            residentsFound = true;
        }
        return residents;
    }
}

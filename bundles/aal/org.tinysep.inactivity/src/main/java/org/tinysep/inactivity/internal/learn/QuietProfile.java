package org.tinysep.inactivity.internal.learn;

import java.time.DayOfWeek;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneId;
import java.time.ZonedDateTime;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;

/**
 * What the home's history says about quiet periods, per room, state and time of day. The states: asleep, and awake
 * in three kinds told apart by what began the quiet period: sitting down (a seat mat turned ON), getting up (a bed
 * mat turned OFF: dressing, making the bed, sitting on its edge, which lasts longer than walking through the
 * bedroom), and moving about (everything else). Asked for
 * a room, a state and a moment, it looks for enough history (quiet periods on {@code minDays} days or more) in
 * this order: the hours around the moment's hour on the same day type (weekday or weekend; only where both day
 * types have enough days), the hours around it on any day, then the room and state at any time of day. Without
 * enough history there is no learned limit (the caller uses the fixed one). Immutable; answers are cached.
 */
public final class QuietProfile {

    private enum DayType { WEEKDAY, WEEKEND }

    /** What began the quiet periods a limit was learned from, in its explanation (none: moving about). */
    private static final String AFTER_SITTING = " after sitting down (a seat mat turned on)";
    private static final String AFTER_GETTING_UP = " after getting up (a bed mat turned off)";

    private record Key(String room, boolean asleep, boolean seated, boolean up, int hour, DayType day) {
    }

    private final Map<String, List<Gap>> byRoom = new HashMap<>();
    private final ZoneId zone;
    private final LearningSettings settings;
    private final Map<Key, Optional<Learned>> cache = new ConcurrentHashMap<>();
    private final String marginWords;

    public QuietProfile(List<Gap> gaps, ZoneId zone, LearningSettings settings) {
        this(gaps, zone, settings, "");
    }

    /**
     * @param settings    with the margin the day-by-day margin check chose ({@link MarginCheck})
     * @param marginWords why that margin, when it is not the configured one (else empty)
     */
    QuietProfile(List<Gap> gaps, ZoneId zone, LearningSettings settings, String marginWords) {
        this.zone = zone;
        this.settings = settings;
        this.marginWords = marginWords;
        for (Gap g : gaps) {
            byRoom.computeIfAbsent(g.start().room(), r -> new ArrayList<>()).add(g);
        }
    }

    /** @return the learned limit for a quiet period beginning at {@code at} in {@code room}, if history suffices */
    public Optional<Learned> learned(String room, String roomName, boolean asleep, Instant at) {
        return learned(room, roomName, asleep, false, at);
    }

    /** As {@link #learned(String, String, boolean, Instant)}, for a quiet period that a seat mat turning ON began. */
    public Optional<Learned> learned(String room, String roomName, boolean asleep, boolean seated, Instant at) {
        return learned(room, roomName, asleep, seated, false, at);
    }

    /** As {@link #learned(String, String, boolean, boolean, Instant)}; {@code up}: a bed mat turned OFF. */
    public Optional<Learned> learned(String room, String roomName, boolean asleep, boolean seated, boolean up,
            Instant at) {
        ZonedDateTime t = at.atZone(zone);
        Key key = new Key(room, asleep, seated && !asleep, up && !asleep, t.getHour(),
                dayType(t.getDayOfWeek()));
        return cache.computeIfAbsent(key, k -> compute(k, roomName));
    }

    private Optional<Learned> compute(Key k, String roomName) {
        List<Gap> all = byRoom.getOrDefault(k.room(), List.of()).stream().filter(g -> g.asleep() == k.asleep()
                && seated(g) == k.seated() && up(g) == k.up()).toList();
        List<Gap> around = all.stream().filter(g -> near(g, k.hour())).toList();
        int from = Math.floorMod(k.hour() - settings.halfWindow(), 24);
        int to = Math.floorMod(k.hour() + settings.halfWindow() + 1, 24);
        String sit = k.seated() ? AFTER_SITTING : k.up() ? AFTER_GETTING_UP : "";
        String hours = (settings.halfWindow() >= 12 ? "at any time of day"
                : String.format("between %02d:00 and %02d:00", from, to)) + sit;
        List<Gap> sameDay = around.stream().filter(g -> dayOf(g) == k.day()).toList();
        List<Gap> otherDay = around.stream().filter(g -> dayOf(g) != k.day()).toList();
        if (days(sameDay).size() >= settings.minDays() && days(otherDay).size() >= settings.minDays()) {
            return Optional.of(learn(sameDay, roomName, k.asleep(),
                    hours + (k.day() == DayType.WEEKEND ? " at weekends" : " on weekdays"), false));
        }
        if (days(around).size() >= settings.minDays()) {
            return Optional.of(learn(around, roomName, k.asleep(), hours, false));
        }
        if (days(all).size() >= settings.minDays()) {
            return Optional.of(learn(all, roomName, k.asleep(), "at any time of day" + sit, true));
        }
        return Optional.empty();
    }

    /**
     * Cold start: what fewer than {@code minDays} days say about a room and state at any time of day.
     *
     * Only whole days count: today's first minutes (a new installation, a test) are not a day of history.
     *
     * @param now the time asked at; quiet periods of its local day are left out
     * @return the learned limit from the room's and state's quiet periods at any time of day, when they lie on at
     *         least one but fewer than {@code minDays} days before today; else empty
     */
    public Optional<Learned> partial(String room, String roomName, boolean asleep, Instant now) {
        return partial(room, roomName, asleep, false, now);
    }

    /** As {@link #partial(String, String, boolean, Instant)}, for a quiet period that a seat mat began. */
    public Optional<Learned> partial(String room, String roomName, boolean asleep, boolean seated, Instant now) {
        return partial(room, roomName, asleep, seated, false, now);
    }

    /** As {@link #partial(String, String, boolean, boolean, Instant)}; {@code up}: a bed mat turned OFF. */
    public Optional<Learned> partial(String room, String roomName, boolean asleep, boolean seated, boolean up,
            Instant now) {
        LocalDate today = now.atZone(zone).toLocalDate();
        boolean sit = seated && !asleep;
        boolean rise = up && !asleep;
        List<Gap> all = byRoom.getOrDefault(room, List.of()).stream().filter(g -> g.asleep() == asleep
                && seated(g) == sit && up(g) == rise && g.start().at().atZone(zone).toLocalDate().isBefore(today))
                .toList();
        int n = days(all).size();
        return n >= 1 && n < settings.minDays() ? Optional.of(learn(all, roomName, asleep, "at any time of day"
                + (sit ? AFTER_SITTING : "")
                + (rise ? AFTER_GETTING_UP : ""), true))
                : Optional.empty();
    }

    private Learned learn(List<Gap> gaps, String roomName, boolean asleep, String scope, boolean allDay) {
        Map<LocalDate, Duration> maxima = days(gaps);
        Duration usual = UsualQuiet.usual(new ArrayList<>(maxima.values()));
        return new Learned(roomName, asleep, scope, usual, UsualQuiet.limit(usual, settings), maxima.size(),
                gaps.size(), allDay);
    }

    /** @return the longest quiet period per local day */
    private Map<LocalDate, Duration> days(List<Gap> gaps) {
        Map<LocalDate, Duration> m = new TreeMap<>();
        for (Gap g : gaps) {
            m.merge(g.start().at().atZone(zone).toLocalDate(), g.length(), (a, b) -> a.compareTo(b) >= 0 ? a : b);
        }
        return m;
    }

    private static boolean seated(Gap g) {
        return g.start().seated() && !g.asleep();
    }

    private static boolean up(Gap g) {
        return g.start().upFromBed() && !g.asleep();
    }

    private boolean near(Gap g, int hour) {
        int h = g.start().at().atZone(zone).getHour();
        int d = Math.abs(h - hour);
        return Math.min(d, 24 - d) <= settings.halfWindow();
    }

    private DayType dayOf(Gap g) {
        return dayType(g.start().at().atZone(zone).getDayOfWeek());
    }

    private static DayType dayType(DayOfWeek d) {
        return d == DayOfWeek.SATURDAY || d == DayOfWeek.SUNDAY ? DayType.WEEKEND : DayType.WEEKDAY;
    }

    /** @return the settings its limits were learned with (the margin may be the day-by-day margin check's) */
    public LearningSettings settings() {
        return settings;
    }

    /** @return why the margin is larger than the configured one, to follow a limit's explanation; else empty */
    public String marginWords() {
        return marginWords;
    }

    /** @return how many different days the history covers (any room) */
    public int historyDays() {
        return days(byRoom.values().stream().flatMap(List::stream).toList()).size();
    }
}

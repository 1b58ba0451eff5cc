package org.tinysep.inactivity.internal.learn;

import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * Signs in the history of more than one person at home: something one person cannot do. A bed mat has been ON for
 * at least {@link #LYING} (someone lies in that bed), and meanwhile there is activity in another room — the one in
 * bed did not get up (the mat did not turn OFF), so someone else made it. Counted by local day: one sensor glitch
 * (a mat's OFF that never came) makes a day or two of such signs, two people make them on most days. A bed span
 * counts for at most {@link #SPAN} from its ON (a lost OFF is not taken for a whole week in bed). Pure Java.
 */
public final class TwoAtOnce {

    /** The bed mat ON at least this long: the person lies there (not sitting down on the edge for a moment). */
    static final Duration LYING = Duration.ofMinutes(10);
    /** A bed mat's ON counts at most this long (a night); beyond, its OFF was lost. */
    static final Duration SPAN = Duration.ofHours(12);

    private static final DateTimeFormatter HM = DateTimeFormatter.ofPattern("HH:mm");

    /**
     * @param days    days of the history (with any activity)
     * @param seen    days of them with a sign of two people at once
     * @param example the last sign in words, or empty
     */
    public record Finding(int days, int seen, String example) {
        /** Nothing seen yet. */
        public static final Finding NONE = new Finding(0, 0, "");

        /**
         * @return whether the home is taken for several residents: signs on at least {@link #MIN_DAYS} days (one lost
         *         OFF, counted for at most {@link #SPAN}, touches at most two) and on at least a quarter of the days
         *         (rare glitches weeks apart do not add up over a month's history)
         */
        public boolean several() {
            return seen >= MIN_DAYS && 4 * seen >= days;
        }

        /** @return why the home is taken for several residents (or not), in plain words */
        public String words() {
            return (several() ? "the home is taken for several residents" : "the home is taken for one resident")
                    + ": seen on " + seen + " of the last " + Amounts.count(days, "day") + " of history, something one "
                    + "person cannot do: activity in another room while a bed mat has been on for "
                    + Amounts.duration(LYING) + " or more" + (example.isEmpty() ? "" : " (the latest " + example + ")");
        }
    }

    /** Signs on at least this many days (and a quarter of the days) make a home of several residents. */
    static final int MIN_DAYS = 3;

    private TwoAtOnce() {
    }

    /**
     * @param sightings the history, in time order
     * @param zone      the home's time zone (the days)
     */
    public static Finding of(List<Sighting> sightings, ZoneId zone) {
        Map<String, Instant> bedSince = new HashMap<>();
        Map<String, String> bedName = new HashMap<>();
        TreeSet<LocalDate> days = new TreeSet<>();
        TreeMap<LocalDate, String> seen = new TreeMap<>();
        for (Sighting s : sightings) {
            if (s.room().isEmpty()) {
                continue; // a device without a room: where it is is not known
            }
            LocalDate day = s.at().atZone(zone).toLocalDate();
            days.add(day);
            for (Map.Entry<String, Instant> b : bedSince.entrySet()) {
                Duration lying = Duration.between(b.getValue(), s.at());
                if (!b.getKey().equals(s.room()) && lying.compareTo(LYING) >= 0 && lying.compareTo(SPAN) <= 0) {
                    LocalTime at = s.at().atZone(zone).toLocalTime();
                    LocalTime since = b.getValue().atZone(zone).toLocalTime();
                    seen.put(day, "on " + day + ": activity in " + s.roomName() + " at " + HM.format(at)
                            + " while the bed mat in " + bedName.get(b.getKey()) + " had been on since "
                            + HM.format(since));
                }
            }
            if (s.upFromBed()) {
                bedSince.remove(s.room());
            } else if (s.inBed()) {
                Instant since = bedSince.get(s.room());
                if (since == null || Duration.between(since, s.at()).compareTo(SPAN) > 0) {
                    bedSince.put(s.room(), s.at()); // a new ON, or one after an ON whose OFF was lost
                }
                bedName.put(s.room(), s.roomName());
            }
        }
        return new Finding(days.size(), seen.size(), seen.isEmpty() ? "" : seen.lastEntry().getValue());
    }
}

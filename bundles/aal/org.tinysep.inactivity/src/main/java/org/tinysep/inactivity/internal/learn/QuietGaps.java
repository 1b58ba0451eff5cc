package org.tinysep.inactivity.internal.learn;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;

/**
 * Cuts a home's history into quiet periods: from each sighting to the next one anywhere in the flat. A period
 * that overlaps a time the flat was empty (Flat Occupancy said UNOCCUPIED) is not a quiet period of the person
 * and is left out, and so is one longer than {@link #MAX_GAP} (a sensor or platform outage, not life).
 */
public final class QuietGaps {

    /** Longer quiet periods are outages, not behaviour; a collapse is reported within this in any case. */
    public static final Duration MAX_GAP = Duration.ofHours(16);

    /** A time the flat was empty. */
    public record Away(Instant from, Instant to) {
        boolean overlaps(Instant a, Instant b) {
            return from.isBefore(b) && to.isAfter(a);
        }
    }

    private QuietGaps() {
    }

    /**
     * @param sightings the history, in time order
     * @param away      the times the flat was empty, in time order
     */
    public static List<Gap> of(List<Sighting> sightings, List<Away> away, SleepRule sleep) {
        List<Gap> gaps = new ArrayList<>();
        int a = 0;
        for (int i = 0; i + 1 < sightings.size(); i++) {
            Sighting s = sightings.get(i);
            Instant end = sightings.get(i + 1).at();
            Duration length = Duration.between(s.at(), end);
            if (length.isNegative() || length.compareTo(MAX_GAP) > 0) {
                continue;
            }
            while (a < away.size() && !away.get(a).to().isAfter(s.at())) {
                a++;
            }
            if (a < away.size() && away.get(a).overlaps(s.at(), end)) {
                continue;
            }
            gaps.add(new Gap(s, sleep.asleep(s), length));
        }
        return gaps;
    }
}

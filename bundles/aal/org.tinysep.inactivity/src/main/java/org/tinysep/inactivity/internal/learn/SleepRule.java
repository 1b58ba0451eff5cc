package org.tinysep.inactivity.internal.learn;

import java.time.Instant;
import java.time.ZoneId;
import java.util.Locale;

/**
 * Decides whether a quiet period that begins with a sighting is sleep: a bed mat says the person is in bed, or the
 * last activity was in a room of type Bedroom during the night hours. Everything else is an awake quiet period,
 * also at night: getting up at 03:00 and going to the bathroom leaves the sleep state, so the bathroom's own
 * (short) limit applies, not the whole night's. A bed mat turning OFF ends sleep too: a person up
 * at night in the bedroom is watched with the bedroom's awake limit learned for those hours, not the night's.
 *
 * @param nightStart first hour of the night (local), 0..23
 * @param nightEnd   first hour after the night (local), 0..23
 * @param zone       the home's time zone
 */
public record SleepRule(int nightStart, int nightEnd, ZoneId zone) {

    public SleepRule {
        if (nightStart < 0 || nightStart > 23 || nightEnd < 0 || nightEnd > 23) {
            throw new IllegalArgumentException("night hours must be 0..23, were " + nightStart + "-" + nightEnd);
        }
    }

    /** @return whether the quiet period after {@code s} is sleep */
    public boolean asleep(Sighting s) {
        return s.inBed() || (!s.upFromBed() && isBedroom(s.roomType()) && night(s.at()));
    }

    /** @return whether {@code at} lies in the night hours */
    public boolean night(Instant at) {
        int h = at.atZone(zone).getHour();
        return nightStart <= nightEnd ? h >= nightStart && h < nightEnd : h >= nightStart || h < nightEnd;
    }

    static boolean isBedroom(String type) {
        return type.toLowerCase(Locale.ROOT).contains("bedroom");
    }
}

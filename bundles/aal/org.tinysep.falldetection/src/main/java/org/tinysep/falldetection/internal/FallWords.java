package org.tinysep.falldetection.internal;

import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import java.util.Optional;

/** A fall in plain words, for the alert's subject and text. */
final class FallWords {

    private static final DateTimeFormatter HM = DateTimeFormatter.ofPattern("HH:mm", Locale.ROOT);
    private final ZoneId zone;

    FallWords(ZoneId zone) {
        this.zone = zone;
    }

    /** @return e.g. "Fall: Anna fell at 14:03" */
    String subject(Fall f, String person) {
        return "Fall: " + who(person) + " fell at " + HM.format(f.impact().atZone(zone));
    }

    /**
     * @return e.g. "a fall was detected at 14:03: a hard impact (3.1 g), then lying still for 4 s; the body turned
     *         by 78° from how it was before the impact (node 0014.4F01.0000.A001); last seen in the Bathroom at
     *         14:01 by its motion sensor. Please check on Anna."
     */
    String text(Fall f, String person, String node, Optional<LastSeen.Sighting> seen) {
        return String.format(Locale.ROOT, "a fall %swas detected at %s: a hard impact (%.1f g), then lying still for "
                + "%d s; the body turned by %.0f° from how it was before the impact (node %s); %s. Please check on %s.",
                person.isBlank() ? "" : "of " + person + " ", HM.format(f.impact().atZone(zone)), f.peakMg() / 1000.0,
                f.still().toSeconds(), f.angleDeg(), node, where(seen), person.isBlank() ? "the person" : person);
    }

    /** @return e.g. "last seen in the Kitchen at 14:02 by its motion sensor", or "no room seen yet" */
    String where(Optional<LastSeen.Sighting> seen) {
        return seen.map(s -> "last seen in " + s.room() + " at " + HM.format(s.at().atZone(zone)) + " by " + s.by())
                .orElse("no room seen yet (no room sensor has reported activity since Fall Detection started)");
    }

    private static String who(String person) {
        return person.isBlank() ? "the person wearing the node" : person;
    }
}

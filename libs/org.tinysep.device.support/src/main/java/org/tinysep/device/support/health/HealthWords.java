package org.tinysep.device.support.health;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;

/** The plain words of sensor health in the event log and device status (one place, so they read alike). */
public final class HealthWords {

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss 'UTC'")
            .withZone(ZoneOffset.UTC);

    private HealthWords() {
    }

    public static String time(Instant t) {
        return t == null ? "never" : TIME.format(t);
    }

    /** @return e.g. "1 h 5 min", "45 s" */
    public static String span(Duration d) {
        long s = Math.max(0, d.getSeconds());
        if (s < 120) {
            return s + " s";
        }
        if (s < 7200) {
            return (s / 60) + " min";
        }
        return (s / 3600) + " h " + (s % 3600 / 60) + " min";
    }

    /** The OFFLINE status detail of a silent node. */
    public static String silentDetail(Instant lastHeard, Duration interval) {
        return "silent since " + time(lastHeard) + " (a report was promised every " + span(interval) + ")";
    }

    /** The PROBLEM entry when a node goes silent. */
    public static String silentProblem(String node, Instant lastHeard, Instant now, Duration interval, int missed) {
        return node + " has not been heard since " + time(lastHeard) + " (" + span(Duration.between(lastHeard, now))
                + " without a report; it promises one every " + span(interval) + ", " + missed
                + " missed reports make it OFFLINE). Is its battery flat, is it out of radio range or broken? "
                + "It is OFFLINE until it is heard again.";
    }

    /** The entry when a silent node is heard again. */
    public static String heardAgain(Instant silentSince, Instant now) {
        return "heard again after " + span(Duration.between(silentSince, now)) + " of silence (last report before: "
                + time(silentSince) + "); ONLINE";
    }

    /** The PROBLEM entry when a node starts flapping: its silence limit is widened (a "monitoring reduced" signal). */
    public static String flapping(String node, int silences, Duration normal, Duration widened) {
        return "Monitoring reduced: " + node + " went silent and came back " + silences + " times within an hour "
                + "(it is OFFLINE after " + span(normal) + " without a report). So that it does not fill the event "
                + "log, it now counts as OFFLINE only after " + span(widened) + " of silence, while this goes on; a "
                + "node that really stops is noticed that much later. Does it only report changes, is it at the edge "
                + "of radio range, or is its battery weak? Check its placement and battery.";
    }

    /** The hourly summary while a node keeps flapping. */
    public static String stillFlapping(String node, int silences, Duration widened) {
        return node + " is still flapping: " + silences + " silences in the last hour; it counts as OFFLINE only "
                + "after " + span(widened) + " of silence.";
    }

    /** The entry when a node stops flapping. */
    public static String flappingEnded(String node, Duration normal) {
        return node + " no longer flaps (fewer than " + FlapDamper.FLAP_LIMIT + " silences in the last hour); it "
                + "counts as OFFLINE after " + span(normal) + " of silence again.";
    }

    /** The PROBLEM entry of a low battery. */
    public static String lowBattery(String node, int millivolts, int threshold) {
        return node + " reports a low battery: " + millivolts + " mV (low below " + threshold
                + " mV). Replace or recharge it soon, before the node stops reporting.";
    }
}

package org.tinysep.sunspot.person.internal;

import java.time.Instant;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.MovementSummary;

/**
 * Since when the node has lain still, from its movement summaries: a summary is still when the magnitude's spread is
 * at most {@value #STILL_SD_MG} mg and its mean points the same way (each axis within {@value #SAME_POSTURE_MG} mg) as
 * at the start of the still run. A worn node is rarely still for long (breathing and small movements of the body move
 * it); a long still run is the first hint that a pendant lies on a table. Thread-safe.
 */
final class Stillness {

    static final int STILL_SD_MG = 30;
    static final int SAME_POSTURE_MG = 150;

    private Acceleration posture;
    private Instant since;

    /** Takes one summary. */
    synchronized void add(MovementSummary s) {
        boolean still = s.magnitudeSdMg() <= STILL_SD_MG;
        if (still && since != null && same(posture, s.mean())) {
            return;
        }
        posture = still ? s.mean() : null;
        since = still ? s.end().minus(s.span()) : null;
    }

    /** @return since when the node lies still, or null while it moves (or before any summary) */
    synchronized Instant since() {
        return since;
    }

    private static boolean same(Acceleration a, Acceleration b) {
        return Math.abs(a.xMg() - b.xMg()) <= SAME_POSTURE_MG && Math.abs(a.yMg() - b.yMg()) <= SAME_POSTURE_MG
                && Math.abs(a.zMg() - b.zMg()) <= SAME_POSTURE_MG;
    }
}

package org.tinysep.simulator.replay;

import java.time.Duration;

/**
 * How well predicted intervals (e.g. Flat Occupancy UNOCCUPIED) agree with reference intervals (e.g. labelled
 * Leaving), by time overlap. Both sides are merged first, so overlapping intervals never count twice.
 *
 * @param reference total reference time
 * @param predicted total predicted time
 * @param overlap   time that is both
 */
public record Agreement(Duration reference, Duration predicted, Duration overlap) {

    /** @return overlap / reference (the share of labelled time that was predicted), NaN if no reference time */
    public double recall() {
        return ratio(overlap, reference);
    }

    /** @return overlap / predicted (the share of predicted time that was labelled), NaN if nothing predicted */
    public double precision() {
        return ratio(overlap, predicted);
    }

    /** @return the harmonic mean of recall and precision, NaN if either is NaN or both are 0 */
    public double f1() {
        double r = recall();
        double p = precision();
        return r + p == 0 ? Double.NaN : 2 * r * p / (r + p);
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT,
                "recall %.3f, precision %.3f (reference %s, predicted %s, overlap %s)",
                recall(), precision(), reference, predicted, overlap);
    }

    private static double ratio(Duration a, Duration b) {
        return b.isZero() ? Double.NaN : (double) a.toMillis() / b.toMillis();
    }
}

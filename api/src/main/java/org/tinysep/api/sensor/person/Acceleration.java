package org.tinysep.api.sensor.person;

import java.util.List;

/**
 * One acceleration sample or mean in thousandths of standard gravity (milli-g), in the node's own axes. At rest
 * the vector points up with a length of about 1000.
 *
 * @param xMg x axis, milli-g
 * @param yMg y axis, milli-g
 * @param zMg z axis, milli-g
 */
public record Acceleration(int xMg, int yMg, int zMg) {

    /** @return the length of the vector, milli-g */
    public double magnitudeMg() {
        return Math.sqrt((double) xMg * xMg + (double) yMg * yMg + (double) zMg * zMg);
    }

    /**
     * The mean vector of samples (or of means of equally long periods), the one way TinySEP averages accelerations:
     * the node's summaries, Fall Detection's postures and the evaluation's padding all use it. Each axis is summed
     * exactly (in a {@code long}) and divided once, then rounded to the nearest milli-g, halves away from zero
     * ({@code 2.5 → 3}, {@code -2.5 → -3}), so the mean of a mirrored list is the mirrored mean.
     *
     * @param samples at least one sample
     * @return the mean of each axis, rounded to whole milli-g
     * @throws IllegalArgumentException when {@code samples} is empty (an empty list has no mean)
     */
    public static Acceleration mean(List<Acceleration> samples) {
        if (samples.isEmpty()) {
            throw new IllegalArgumentException("the mean of no accelerations is undefined: give at least one sample");
        }
        long x = 0;
        long y = 0;
        long z = 0;
        for (Acceleration a : samples) {
            x += a.xMg();
            y += a.yMg();
            z += a.zMg();
        }
        int n = samples.size();
        return new Acceleration(rounded(x, n), rounded(y, n), rounded(z, n));
    }

    /** @return sum / n to the nearest whole number, halves away from zero */
    private static int rounded(long sum, int n) {
        long q = sum / n;
        long twiceRest = 2 * Math.abs(sum % n);
        if (twiceRest >= n) {
            q += sum < 0 ? -1 : 1;
        }
        return (int) q;
    }
}

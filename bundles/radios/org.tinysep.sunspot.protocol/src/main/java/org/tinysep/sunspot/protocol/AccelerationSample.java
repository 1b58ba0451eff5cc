package org.tinysep.sunspot.protocol;

/**
 * One acceleration vector as the person node sends it (a burst sample or a summary's mean): three signed 16-bit
 * big-endian numbers of milli-g, in the node's own axes. Each axis must lie within ±{@value #LIMIT_MG} mg (16 g,
 * more than any accelerometer a Sun SPOT carries): a value beyond it cannot have been measured.
 *
 * @param xMg x axis, milli-g
 * @param yMg y axis, milli-g
 * @param zMg z axis, milli-g
 */
public record AccelerationSample(int xMg, int yMg, int zMg) {

    /** Largest absolute value of one axis, milli-g. */
    public static final int LIMIT_MG = 16_000;
    /** Bytes of one sample on the wire. */
    static final int LENGTH = 6;

    /** @throws IllegalArgumentException if an axis is beyond ±{@value #LIMIT_MG} mg */
    public AccelerationSample {
        check("x", xMg);
        check("y", yMg);
        check("z", zMg);
    }

    /** @return the length of the vector, milli-g */
    public double magnitudeMg() {
        return Math.sqrt((double) xMg * xMg + (double) yMg * yMg + (double) zMg * zMg);
    }

    /** @return why the axis value cannot be measured, or null if it can */
    static String fault(String axis, int mg) {
        return Math.abs(mg) > LIMIT_MG ? axis + " axis " + mg + " mg is beyond ±" + LIMIT_MG + " mg" : null;
    }

    private static void check(String axis, int mg) {
        String fault = fault(axis, mg);
        if (fault != null) {
            throw new IllegalArgumentException(fault);
        }
    }
}

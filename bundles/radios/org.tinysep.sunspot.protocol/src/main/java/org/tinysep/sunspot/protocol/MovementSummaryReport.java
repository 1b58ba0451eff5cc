package org.tinysep.sunspot.protocol;

/**
 * Person node movement summary {@code 6 0x21 ...} (TinySEP, protocol 2.2.0), 14 bytes: what the node measured over
 * its last summary period (normally 2 s). The receiver takes the frame's arrival as the period's end.
 * <p>
 * Limits (a value beyond them cannot have been measured, and the decoder refuses it): span 1..65535 ms; each mean
 * axis within ±{@value AccelerationSample#LIMIT_MG} mg; magnitude SD and peak 0..{@value #MAX_MAGNITUDE_MG} mg;
 * the SD not above the peak; the mean vector's length not above the peak by more than
 * {@value #ROUNDING_MG} mg (the mean of vectors is never longer than the longest of them; the slack absorbs
 * rounding to whole milli-g).
 *
 * @param spanMillis    the period's length, ms, 1..65535
 * @param mean          mean acceleration over the period
 * @param magnitudeSdMg standard deviation of the magnitude, mg
 * @param peakMg        highest magnitude in the period, mg
 */
public record MovementSummaryReport(int spanMillis, AccelerationSample mean, int magnitudeSdMg, int peakMg)
        implements SunSpotPayload {

    /** Largest magnitude a vector of three axes within the limit can have: ⌈16000 · √3⌉ mg. */
    public static final int MAX_MAGNITUDE_MG = 27_713;
    /** How far the mean's length may exceed the peak, mg (rounding). */
    public static final int ROUNDING_MG = 2;

    /** @throws IllegalArgumentException if a value breaks a limit above; NullPointerException if mean is null */
    public MovementSummaryReport {
        String fault = fault(spanMillis, mean, magnitudeSdMg, peakMg);
        if (fault != null) {
            throw new IllegalArgumentException(fault);
        }
    }

    /** @return why these values cannot come from a node, in words, or null if they can */
    static String fault(int spanMillis, AccelerationSample mean, int magnitudeSdMg, int peakMg) {
        if (spanMillis < 1 || spanMillis > 0xFFFF) {
            return "span " + spanMillis + " ms, expected 1..65535";
        }
        if (peakMg < 0 || peakMg > MAX_MAGNITUDE_MG) {
            return "peak " + peakMg + " mg, expected 0.." + MAX_MAGNITUDE_MG;
        }
        if (magnitudeSdMg < 0 || magnitudeSdMg > peakMg) {
            return "magnitude SD " + magnitudeSdMg + " mg, expected 0..peak " + peakMg + " mg";
        }
        if (mean.magnitudeMg() > peakMg + ROUNDING_MG) {
            return "mean vector " + Math.round(mean.magnitudeMg()) + " mg long, above the peak " + peakMg + " mg";
        }
        return null;
    }

    @Override
    public SunSpotSensorType sensorType() {
        return SunSpotSensorType.PERSON;
    }
}

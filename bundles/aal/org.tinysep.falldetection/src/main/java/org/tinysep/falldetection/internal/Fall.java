package org.tinysep.falldetection.internal;

import java.time.Duration;
import java.time.Instant;
import org.tinysep.api.sensor.person.Acceleration;

/**
 * A fall the detector saw.
 *
 * @param impact     when the highest sample of the impact's burst was taken
 * @param peakMg     that sample's magnitude, milli-g
 * @param before     mean acceleration before the impact (posture then)
 * @param after      mean acceleration while still after it (posture now)
 * @param angleDeg   the angle between the two, degrees
 * @param still      how long the person has been still
 * @param detectedAt when the stillness was long enough (the end of the last still summary)
 */
public record Fall(Instant impact, int peakMg, Acceleration before, Acceleration after, double angleDeg,
        Duration still, Instant detectedAt) {
}

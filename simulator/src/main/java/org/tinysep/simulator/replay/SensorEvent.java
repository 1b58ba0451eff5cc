package org.tinysep.simulator.replay;

import java.time.LocalDateTime;
import java.util.Objects;

/**
 * One state change of a recorded sensor: the common event model every replay reader produces.
 *
 * @param time   local time of the change (no zone, as recorded)
 * @param sensor sensor identity, unique within one recording (e.g. {@code Basin}, {@code Door Kitchen})
 * @param room   room the sensor is in as recorded; may be empty
 * @param kind   what the sensor senses
 * @param on     true for ON / OPEN, false for OFF / CLOSE
 */
public record SensorEvent(LocalDateTime time, String sensor, String room, Kind kind, boolean on) {

    /** @throws NullPointerException if a field is null; IllegalArgumentException if the sensor is blank */
    public SensorEvent {
        Objects.requireNonNull(time, "time");
        Objects.requireNonNull(sensor, "sensor");
        Objects.requireNonNull(room, "room");
        Objects.requireNonNull(kind, "kind");
        if (sensor.isBlank()) {
            throw new IllegalArgumentException("sensor name is blank");
        }
    }
}

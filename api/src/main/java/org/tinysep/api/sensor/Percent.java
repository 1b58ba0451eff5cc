package org.tinysep.api.sensor;

/**
 * A percentage from 0 to 100 inclusive: brightness, heater potency, speaker volume.
 *
 * @param value the percentage
 */
public record Percent(int value) implements Comparable<Percent> {

    public static final Percent ZERO = new Percent(0);
    public static final Percent FULL = new Percent(100);

    public Percent {
        if (value < 0 || value > 100) {
            throw new IllegalArgumentException("percentage must be 0..100, was " + value);
        }
    }

    public static Percent of(int value) {
        return new Percent(value);
    }

    @Override
    public int compareTo(Percent o) {
        return Integer.compare(value, o.value);
    }

    @Override
    public String toString() {
        return value + "%";
    }
}

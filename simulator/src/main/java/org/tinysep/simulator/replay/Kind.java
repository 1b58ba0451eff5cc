package org.tinysep.simulator.replay;

import java.util.Locale;

/**
 * What a recorded sensor senses (simulator/README-replay.md "Generic: events.csv and labels.csv"); written lower case
 * in events.csv.
 */
public enum Kind {
    /** Passive infrared motion sensor. */
    MOTION,
    /** Magnetic contact (reed switch) on a door, a cupboard, a fridge... */
    DOOR,
    /** Pressure mat (seat, bed). */
    PRESSURE,
    /** Toilet flush. */
    FLUSH,
    /** Electric appliance in use (microwave, toaster). */
    ELECTRIC,
    /** Anything else that is on or off. */
    OTHER;

    /** @return the name used in events.csv and mapping files, e.g. {@code motion} */
    public String csvName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * @param text a kind name, case-insensitive, e.g. {@code motion}
     * @return the kind
     * @throws IllegalArgumentException naming the allowed values if the text is not a kind
     */
    public static Kind parse(String text) {
        for (Kind k : values()) {
            if (k.csvName().equalsIgnoreCase(text == null ? "" : text.trim())) {
                return k;
            }
        }
        throw new IllegalArgumentException("unknown sensor kind '" + text
                + "'; expected one of motion, door, pressure, flush, electric, other");
    }
}

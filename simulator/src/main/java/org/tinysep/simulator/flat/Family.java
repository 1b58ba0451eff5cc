package org.tinysep.simulator.flat;

import java.util.Locale;

/** The node family: which wire protocol a simulated node speaks. */
public enum Family {
    AMICA, SUNSPOT;

    /** @return the family for {@code AmICA} or {@code SunSPOT} (case-insensitive), or null */
    public static Family parse(String text) {
        return switch (text.trim().toLowerCase(Locale.ROOT)) {
        case "amica" -> AMICA;
        case "sunspot", "sun-spot", "sun spot" -> SUNSPOT;
        default -> null;
        };
    }
}

package org.tinysep.device.support.lifecycle;

import java.util.Locale;
import org.tinysep.api.sensor.Percent;

/**
 * Parses parameter values typed by a user ({@code tinysep:set <uid> <key> <value>}) into API types. A bad value
 * gives an {@link IllegalArgumentException} whose message names the key, the accepted form and the value.
 */
public final class ParameterValues {

    private ParameterValues() {
    }

    /**
     * @param key  the parameter, for the message
     * @param text a whole number 0..100, optionally followed by {@code %}, e.g. {@code 40} or {@code 40%}
     * @return the percentage
     */
    public static Percent percent(String key, String text) {
        String t = text == null ? "" : text.strip();
        if (t.endsWith("%")) {
            t = t.substring(0, t.length() - 1).strip();
        }
        try {
            int v = Integer.parseInt(t);
            if (v >= 0 && v <= 100) {
                return Percent.of(v);
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException(key + " must be a whole percentage 0..100, was '" + text + "'");
    }

    /**
     * @param key  the parameter, for the message
     * @param text {@code true}/{@code false} or {@code on}/{@code off}, any case
     * @return the flag
     */
    public static boolean bool(String key, String text) {
        String t = text == null ? "" : text.strip().toLowerCase(Locale.ROOT);
        return switch (t) {
            case "true", "on" -> true;
            case "false", "off" -> false;
            default -> throw new IllegalArgumentException(key + " must be true or false (or on/off), was '" + text
                    + "'");
        };
    }
}

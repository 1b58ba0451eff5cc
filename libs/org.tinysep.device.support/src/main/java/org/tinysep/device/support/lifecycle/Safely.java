package org.tinysep.device.support.lifecycle;

import java.util.function.Supplier;

/**
 * Calls into other bundles' objects (devices, drivers, services that may be going away or may throw) without letting
 * their exceptions escape, and describes a failure in one line for an event or a status.
 */
public final class Safely {

    private Safely() {
    }

    /** @return {@code call}'s result, or {@code fallback} if it throws or returns null */
    public static <T> T get(Supplier<T> call, T fallback) {
        try {
            T value = call.get();
            return value == null ? fallback : value;
        } catch (RuntimeException e) {
            return fallback;
        }
    }

    /** @return a one-line description of a failure: the exception's simple class name and message */
    public static String describe(Throwable t) {
        String message = t.getMessage();
        String name = t.getClass().getSimpleName();
        return message == null || message.isBlank() ? name : name + ": " + oneLine(message);
    }

    /** @return {@code text} on one line (line breaks and tabs as one space), "" for null */
    public static String oneLine(String text) {
        return text == null ? "" : text.replaceAll("[\\r\\n\\t]+", " ").strip();
    }
}

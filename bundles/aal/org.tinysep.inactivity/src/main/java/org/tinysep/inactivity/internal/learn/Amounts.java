package org.tinysep.inactivity.internal.learn;

import java.time.Duration;
import java.util.Locale;

/** Durations and numbers in plain words. */
public final class Amounts {

    private Amounts() {
    }

    /** @return e.g. "40 min", "2 h", "1 h 10 min", "45 s" */
    public static String duration(Duration d) {
        long s = Math.max(0, d.getSeconds());
        if (s < 60) {
            return s + " s";
        }
        long m = (s + 30) / 60;
        if (m < 60) {
            return m + " min";
        }
        return m % 60 == 0 ? m / 60 + " h" : m / 60 + " h " + m % 60 + " min";
    }

    /** @return e.g. "1 day", "21 days" */
    public static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }

    static String factor(double f) {
        return f == Math.rint(f) ? Long.toString((long) f) : String.format(Locale.ROOT, "%.2f", f)
                .replaceAll("0+$", "");
    }
}

package org.tinysep.web.api.internal;

/** Text helpers for log lines holding user input. */
final class Strings {

    private Strings() {
    }

    /** @return {@code s} without control characters, cut to {@code max} characters */
    static String shorten(String s, int max) {
        String clean = s.replaceAll("\\p{Cntrl}", "?");
        return clean.length() <= max ? clean : clean.substring(0, max) + "…";
    }
}

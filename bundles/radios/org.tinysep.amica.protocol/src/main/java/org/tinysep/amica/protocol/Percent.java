package org.tinysep.amica.protocol;

/** Range check shared by the percentage payloads; package-private helper. */
final class Percent {

    static final int MAX = 100;

    private Percent() {
    }

    static void check(int percent) {
        if (percent < 0 || percent > MAX) {
            throw new IllegalArgumentException("percent " + percent + " is outside 0..100");
        }
    }
}

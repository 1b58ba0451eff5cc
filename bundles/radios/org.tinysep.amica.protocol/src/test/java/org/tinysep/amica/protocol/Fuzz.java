package org.tinysep.amica.protocol;

import java.util.Random;

/**
 * Runs a check over many random cases, reproducibly: case {@code i} of base seed {@code s} always gets the same
 * {@link Random} ({@link #caseRandom(long, int)}), and a failure names both. Replay one case with
 * {@code mvn test -Dtest=<Class>#<method> -Dfuzz.seed=<s> -Dfuzz.case=<i>}; {@code -Dfuzz.seed} alone runs every
 * check on other cases. Also random values biased towards the edges (empty, smallest, largest), where bugs live.
 * <p>
 * Shared with the tests of other protocol modules through this module's test jar
 * ({@code <type>test-jar</type>}, scope test).
 */
public final class Fuzz {

    /** One case: draws everything it needs from {@code random}. */
    @FunctionalInterface
    public interface Case {
        void check(Random random) throws Exception;
    }

    private Fuzz() {
    }

    /**
     * Runs {@code cases} cases of {@code check}.
     *
     * @param seed the test's fixed base seed; system property {@code fuzz.seed} overrides it
     * @throws AssertionError naming the seed and case index of the first failing case, with its failure as cause
     */
    public static void forAll(long seed, int cases, Case check) {
        long base = Long.getLong("fuzz.seed", seed);
        Integer only = Integer.getInteger("fuzz.case");
        for (int i = only == null ? 0 : only; i < (only == null ? cases : only + 1); i++) {
            try {
                check.check(caseRandom(base, i));
            } catch (Exception | AssertionError e) {
                throw new AssertionError("seed " + base + ", case " + i + " of " + cases
                        + " failed (replay: -Dfuzz.seed=" + base + " -Dfuzz.case=" + i + "): " + e.getMessage(), e);
            }
        }
    }

    /** @return the random source of case {@code index} of base seed {@code seed} */
    public static Random caseRandom(long seed, int index) {
        return new Random(seed * 0x9E3779B97F4A7C15L + index);
    }

    /** @return {@code min..max}; {@code min} one time in sixteen, {@code max} one time in sixteen */
    public static int between(Random r, int min, int max) {
        return switch (r.nextInt(16)) {
            case 0 -> min;
            case 1 -> max;
            default -> min + r.nextInt(max - min + 1);
        };
    }

    /** @return any long; 0, ±1, MIN_VALUE or MAX_VALUE one time in eight */
    public static long anyLong(Random r) {
        return r.nextInt(8) == 0 ? new long[] {0, 1, -1, Long.MIN_VALUE, Long.MAX_VALUE}[r.nextInt(5)] : r.nextLong();
    }

    /** @return any byte; 0, ±1, -128 or 127 one time in eight */
    public static byte anyByte(Random r) {
        return r.nextInt(8) == 0 ? new byte[] {0, 1, -1, Byte.MIN_VALUE, Byte.MAX_VALUE}[r.nextInt(5)]
                : (byte) r.nextInt(256);
    }

    /** @return {@code minSize..maxSize} (edge-biased) bytes of {@link #anyByte} */
    public static byte[] bytes(Random r, int minSize, int maxSize) {
        byte[] out = new byte[between(r, minSize, maxSize)];
        for (int i = 0; i < out.length; i++) {
            out[i] = anyByte(r);
        }
        return out;
    }

    /** @return 0..maxSize bytes */
    public static byte[] bytes(Random r, int maxSize) {
        return bytes(r, 0, maxSize);
    }

    /** @return an index into {@code weights}, each drawn in proportion to its weight */
    public static int weighted(Random r, int... weights) {
        int total = 0;
        for (int w : weights) {
            total += w;
        }
        int pick = r.nextInt(total);
        for (int i = 0; ; i++) {
            pick -= weights[i];
            if (pick < 0) {
                return i;
            }
        }
    }
}

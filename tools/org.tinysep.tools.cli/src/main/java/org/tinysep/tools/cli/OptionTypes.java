package org.tinysep.tools.cli;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Option value types the tools share, for {@code @Option(converter = ...)}: each refuses a bad value with what it
 * needs and what it got, e.g. {@code Invalid value for option '--amica-port': needs a port 1..65535, not '70000'}.
 */
public final class OptionTypes {

    private OptionTypes() {
    }

    /** A UDP or TCP port, 1..65535. */
    public static final class Port implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            return whole(value, 1, 65535, "a port 1..65535");
        }
    }

    /** A whole number >= 0 (a count, a number of days, seconds, minutes). */
    public static final class Count implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            return whole(value, 0, Integer.MAX_VALUE, "a whole number >= 0");
        }
    }

    /** A whole number >= 1 (processes at once, repetitions). */
    public static final class AtLeastOne implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            return whole(value, 1, Integer.MAX_VALUE, "a whole number >= 1");
        }
    }

    /** A random seed: a whole number >= 0. */
    public static final class Seed implements ITypeConverter<Long> {
        @Override
        public Long convert(String value) {
            try {
                long n = Long.parseLong(value.trim());
                if (n >= 0) {
                    return n;
                }
            } catch (NumberFormatException e) {
                // said below
            }
            throw new TypeConversionException("needs a whole number >= 0, not '" + value + "'");
        }
    }

    private static int whole(String value, int min, int max, String what) {
        try {
            int n = Integer.parseInt(value.trim());
            if (n >= min && n <= max) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new TypeConversionException("needs " + what + ", not '" + value + "'");
    }
}

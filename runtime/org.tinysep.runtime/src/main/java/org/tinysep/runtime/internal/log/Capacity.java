package org.tinysep.runtime.internal.log;

import java.util.function.IntSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.runtime.internal.RuntimeConfig;

/** Reads whole-number settings (ring capacities, log-file limits) from the configuration, rejecting bad values. */
final class Capacity {

    private static final Logger LOG = LoggerFactory.getLogger(Capacity.class);

    private Capacity() {
    }

    /**
     * @param value   reads the configured value (a typed-configuration method, which may throw on bad input)
     * @param current the capacity kept when the value is bad
     * @return the value if it lies in 1..{@link RingBuffer#MAX_CAPACITY}, else {@code current}
     */
    static int read(String key, IntSupplier value, int current) {
        return read(key, value, 1, RingBuffer.MAX_CAPACITY, current);
    }

    /** @return the value if it is a whole number in {@code min..max}, else {@code fallback} (with a WARN) */
    static int read(String key, IntSupplier value, int min, int max, int fallback) {
        int v;
        try {
            v = value.getAsInt();
        } catch (RuntimeException e) {
            LOG.warn("Configuration {}: {} is not a whole number ({}); using {}", RuntimeConfig.PID, key,
                    e.toString(), fallback);
            return fallback;
        }
        if (v < min || v > max) {
            LOG.warn("Configuration {}: {}={} is outside {}..{}; using {}", RuntimeConfig.PID, key, v, min, max,
                    fallback);
            return fallback;
        }
        return v;
    }
}

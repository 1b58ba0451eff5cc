package org.tinysep.runtime.internal;

import java.util.function.IntSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Reads a ring capacity from the configuration, rejecting bad values with a log entry. */
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
        int v;
        try {
            v = value.getAsInt();
        } catch (RuntimeException e) {
            LOG.warn("Configuration {}: {} is not a whole number ({}); keeping {}", RuntimeConfig.PID, key,
                    e.toString(), current);
            return current;
        }
        if (v < 1 || v > RingBuffer.MAX_CAPACITY) {
            LOG.warn("Configuration {}: {}={} is outside 1..{}; keeping {}", RuntimeConfig.PID, key, v,
                    RingBuffer.MAX_CAPACITY, current);
            return current;
        }
        return v;
    }
}

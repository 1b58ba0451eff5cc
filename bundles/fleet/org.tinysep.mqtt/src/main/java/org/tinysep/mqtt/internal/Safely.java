package org.tinysep.mqtt.internal;

import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Reads from another bundle's service without letting its failure stop the bridge. */
final class Safely {

    private static final Logger LOG = LoggerFactory.getLogger(Safely.class);

    private Safely() {
    }

    static <T> T get(Supplier<T> s, T fallback) {
        try {
            return s.get();
        } catch (RuntimeException e) {
            LOG.debug("a service failed to answer the MQTT bridge: {}", e.toString());
            return fallback;
        }
    }
}

package org.tinysep.web.api.internal;

import java.util.function.Supplier;
import org.tinysep.api.device.Device;

/** Calls into devices and drivers that may be going away or may throw: a failure gives the fallback. */
final class Safe {

    private Safe() {
    }

    static <T> T get(Supplier<T> call, T fallback) {
        try {
            T v = call.get();
            return v == null ? fallback : v;
        } catch (RuntimeException e) {
            return fallback;
        }
    }

    static String name(Device d, String fallback) {
        return get(d::name, fallback);
    }
}

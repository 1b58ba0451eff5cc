package org.tinysep.web.api.internal;

import org.tinysep.device.support.lifecycle.Safely;
import java.util.Map;

/** Device and driver names for live log entries, looked up in the registry at most once a second. */
final class NameCache {

    private static final long MAX_AGE_NANOS = 1_000_000_000L;

    private final PlatformView platform;
    private volatile Map<String, String> names = Map.of();
    private volatile long readAt = System.nanoTime() - 2 * MAX_AGE_NANOS;

    NameCache(PlatformView platform) {
        this.platform = platform;
    }

    Map<String, String> get() {
        long now = System.nanoTime();
        if (now - readAt > MAX_AGE_NANOS) {
            names = Safely.get(platform::names, names);
            readAt = now;
        }
        return names;
    }
}

package org.tinysep.runtime.internal.log;

import java.time.Clock;
import java.time.Instant;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.service.TimeControllerProvider;

/**
 * The platform's time for log entries: the bound Time Controller's {@code now()} when there is one, else the
 * fallback clock (the system clock in the framework, a fixed clock in tests). Lock-free.
 */
final class LogClock {

    private static final Logger LOG = LoggerFactory.getLogger(LogClock.class);

    private final Clock fallback;
    private final AtomicReference<TimeControllerProvider> controller = new AtomicReference<>();
    private final AtomicBoolean warned = new AtomicBoolean();

    LogClock(Clock fallback) {
        this.fallback = fallback;
    }

    /** Uses {@code provider} from now on (a greedy reference binds the new one before unbinding the old). */
    void use(TimeControllerProvider provider) {
        controller.set(provider);
        warned.set(false);
    }

    /** Stops using {@code provider}, unless another one has already replaced it. */
    void release(TimeControllerProvider provider) {
        controller.compareAndSet(provider, null);
    }

    Instant now() {
        TimeControllerProvider provider = controller.get();
        if (provider != null) {
            try {
                Instant t = provider.now();
                if (t != null) {
                    return t;
                }
            } catch (RuntimeException e) {
                if (warned.compareAndSet(false, true)) {
                    LOG.warn("Time Controller failed to tell the time; using the system clock: {}", e.toString());
                }
            }
        }
        return fallback.instant();
    }
}

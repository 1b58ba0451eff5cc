package org.tinysep.device.support.time;

import java.time.Instant;
import java.util.function.Supplier;
import org.osgi.framework.BundleContext;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.service.TimeControllerProvider;

/**
 * The platform's time: the Time Controller's when one is present (it may run in virtual time), otherwise the
 * system clock.
 */
public final class PlatformClock implements AutoCloseable {

    private final Supplier<Instant> now;
    private final Runnable onClose;

    /** A clock from an explicit source; for tests and tools outside a framework. */
    public PlatformClock(Supplier<Instant> now) {
        this(now, () -> { });
    }

    private PlatformClock(Supplier<Instant> now, Runnable onClose) {
        this.now = now;
        this.onClose = onClose;
    }

    /** The Time Controller's time while one is registered, the system clock otherwise. */
    public static PlatformClock tracking(BundleContext context) {
        ServiceTracker<TimeControllerProvider, TimeControllerProvider> time =
                new ServiceTracker<>(context, TimeControllerProvider.class, null);
        time.open();
        return new PlatformClock(() -> {
            TimeControllerProvider t = time.getService();
            return t == null ? Instant.now() : t.now();
        }, time::close);
    }

    public Instant now() {
        return now.get();
    }

    @Override
    public void close() {
        onClose.run();
    }
}

package org.tinysep.device.support;

import java.time.Instant;
import org.osgi.framework.BundleContext;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.api.service.TimeControllerProvider;

/**
 * The platform's time: the Time Controller's when one is present (it may run in virtual time), otherwise the
 * system clock.
 */
public final class PlatformClock implements AutoCloseable {

    private final ServiceTracker<TimeControllerProvider, TimeControllerProvider> time;

    public PlatformClock(BundleContext context) {
        time = new ServiceTracker<>(context, TimeControllerProvider.class, null);
        time.open();
    }

    public Instant now() {
        TimeControllerProvider t = time.getService();
        return t == null ? Instant.now() : t.now();
    }

    @Override
    public void close() {
        time.close();
    }
}

package org.tinysep.device.support.time;

import java.time.Instant;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.util.tracker.ServiceTracker;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Connection;
import org.tinysep.api.service.TimeControllerListener;
import org.tinysep.api.service.TimeControllerProvider;

/**
 * One tick per platform second for time-dependent logic (timeouts, leave checks, inactivity limits). While a Time
 * Controller is registered, ticks are its {@code timeAdvanced} events, so the logic runs in its time, virtual time
 * included, and tests never sleep. Without one, a scheduler of this ticker ticks every real second with the system
 * clock. A tick callback that throws is logged; the next tick comes all the same.
 */
public final class PlatformTicker implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(PlatformTicker.class);

    private final String name;
    private final Consumer<Instant> onTick;
    private final ScheduledExecutorService scheduler;
    private final ServiceTracker<TimeControllerProvider, Connection> tracker;
    private ScheduledFuture<?> ownTicks;

    /**
     * Starts ticking at once.
     *
     * @param name   names the scheduler thread and log messages
     * @param onTick called with the platform time of each tick, never concurrently
     */
    public PlatformTicker(BundleContext context, String name, Consumer<Instant> onTick) {
        this.name = name;
        this.onTick = onTick;
        this.scheduler = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, name + "-ticker"));
        this.tracker = new ServiceTracker<>(context, TimeControllerProvider.class, null) {
            @Override
            public Connection addingService(ServiceReference<TimeControllerProvider> ref) {
                TimeControllerProvider time = context.getService(ref);
                if (time == null) {
                    return null;
                }
                Connection c = time.connect(new TimeControllerListener() {
                    @Override
                    public void timeAdvanced(TimeControllerProvider source, Instant now) {
                        tick(now);
                    }
                });
                useOwnTicks(false);
                return c;
            }

            @Override
            public void removedService(ServiceReference<TimeControllerProvider> ref, Connection c) {
                c.close();
                context.ungetService(ref);
                useOwnTicks(size() == 0); // the removed one is no longer counted here
            }
        };
        useOwnTicks(true);
        tracker.open();
    }

    private synchronized void useOwnTicks(boolean own) {
        if (own && ownTicks == null && !scheduler.isShutdown()) {
            ownTicks = scheduler.scheduleAtFixedRate(() -> tick(Instant.now()), 1, 1, TimeUnit.SECONDS);
        } else if (!own && ownTicks != null) {
            ownTicks.cancel(false);
            ownTicks = null;
        }
    }

    private synchronized void tick(Instant now) {
        try {
            onTick.accept(now);
        } catch (RuntimeException e) {
            LOG.warn("{}: tick at {} failed; the next one comes all the same: {}", name, now, e.toString());
            LOG.debug("detail", e);
        }
    }

    @Override
    public void close() {
        tracker.close();
        scheduler.shutdownNow();
    }
}

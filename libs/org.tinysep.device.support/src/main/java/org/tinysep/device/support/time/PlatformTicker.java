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
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.TimeControllerListener;
import org.tinysep.api.service.TimeControllerProvider;

/**
 * One tick per platform second for time-dependent logic (timeouts, leave checks, inactivity limits). While a Time
 * Controller is registered, ticks are its {@code timeAdvanced} events, so the logic runs in its time, virtual time
 * included, and tests never sleep. Without one, a scheduler of this ticker ticks every real second with the system
 * clock. A tick callback that throws is logged; the next tick comes all the same.
 * <p>
 * A component that knows when it next has something to do ({@link #whenDue}) is called only then: its {@link Due}
 * returns the time of the next tick it needs, and {@link #wake} brings that forward when an event starts a timer.
 * The ticks still come every second (the Time Controller's, or this ticker's own), but one that finds nothing due
 * does not reach the component (an idle platform's components do no work between their due times). A clock that goes
 * back or changes mode always reaches it, so its times are re-based as before.
 */
public final class PlatformTicker implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(PlatformTicker.class);

    private final String name;
    private final TickGate gate;
    private final ScheduledExecutorService scheduler;
    private final ServiceTracker<TimeControllerProvider, Connection> tracker;
    private ScheduledFuture<?> ownTicks;

    /**
     * Starts ticking at once; every tick calls {@code onTick}.
     *
     * @param name   names the scheduler thread and log messages
     * @param onTick called with the platform time of each tick, never concurrently
     */
    public PlatformTicker(BundleContext context, String name, Consumer<Instant> onTick) {
        this(context, name, now -> {
            onTick.accept(now);
            return now; // every tick
        });
    }

    /**
     * Starts ticking at once; a tick calls {@code onTick} only when it is due (its first tick always is).
     *
     * @param name   names the scheduler thread and log messages
     * @param onTick called with the platform time of a tick when due, never concurrently; returns when it is next due
     */
    public static PlatformTicker whenDue(BundleContext context, String name, Due onTick) {
        return new PlatformTicker(context, name, onTick);
    }

    private PlatformTicker(BundleContext context, String name, Due onTick) {
        this.name = name;
        this.gate = new TickGate(onTick);
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

                    @Override
                    public void modeChanged(TimeControllerProvider source, ClockMode mode, Instant at) {
                        gate.next();
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
            gate.tick(now);
        } catch (RuntimeException e) {
            LOG.warn("{}: tick at {} failed; the next one comes all the same: {}", name, now, e.toString());
            LOG.debug("detail", e);
        }
    }

    /**
     * Something became due at platform time {@code at} (an event started a timer, earlier than the component last
     * said): the first tick at or after it calls the component. Any thread; {@code null} is ignored.
     */
    public void wake(Instant at) {
        gate.wake(at);
    }

    /** The next tick calls the component, whatever it last asked for (e.g. its settings changed). Any thread. */
    public void wakeNext() {
        gate.next();
    }

    @Override
    public void close() {
        tracker.close();
        scheduler.shutdownNow();
    }
}

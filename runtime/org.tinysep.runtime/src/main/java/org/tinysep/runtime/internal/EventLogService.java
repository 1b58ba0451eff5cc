package org.tinysep.runtime.internal;

import java.time.Clock;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Consumer;
import java.util.function.IntSupplier;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.LogHistory;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.service.TimeControllerProvider;

/**
 * The platform's {@link EventLog}: an in-memory ring stamped with the platform time, kept on disk as
 * {@code events-*.log} ({@link PersistentLog}) and reloaded on start. {@link #record} is O(1) and does no I/O on
 * the caller's thread; every entry is echoed to SLF4J logger {@code tinysep.events} at INFO
 * ({@code <kind> <origin> <message>}) from one background thread and written to the files from another.
 */
@Component(service = EventLog.class, configurationPid = RuntimeConfig.PID)
@Designate(ocd = RuntimeConfig.class)
public final class EventLogService implements EventLog {

    private static final Logger EVENTS = LoggerFactory.getLogger("tinysep.events");

    private final PlatformClock clock;
    private final RingBuffer<EventEntry> ring = new RingBuffer<>(10_000);
    private final HistoryKeeper<EventEntry> history;
    private volatile EventForwarder forwarder;
    private ExecutorService executor;

    public EventLogService() {
        this(Clock.systemUTC());
    }

    EventLogService(Clock fallback) {
        this.clock = new PlatformClock(fallback);
        this.history = new HistoryKeeper<>(ring, new EventLines(), "events", Clock.systemUTC());
    }

    @Activate
    void activate(RuntimeConfig config, BundleContext context) {
        configure(config::eventCapacity);
        persist(LogConfig.read(config, context));
        executor = Executors.newSingleThreadExecutor(Threads.named("tinysep-event-log"));
        start(config::eventCapacity, executor, e -> EVENTS.info("{} {} {}", e.kind(), e.origin(), e.message()));
    }

    @Modified
    void modified(RuntimeConfig config, BundleContext context) {
        configure(config::eventCapacity);
        persist(LogConfig.read(config, context));
    }

    @Deactivate
    void deactivate() {
        forwarder = null;
        executor.shutdown(); // a pending drain still runs; nothing waits for it
        history.close(); // writes what is left and forces it to the disk
    }

    /**
     * Keeps the history in files as {@code settings} say (null: memory only). Called before {@link #start} on
     * activation, it reloads the ring from the files; damaged lines are reported in the log itself.
     */
    void persist(LogSettings settings) {
        long damaged = history.apply(settings);
        if (damaged > 0) {
            record(EventKind.PROBLEM, "event-log", damaged + " damaged lines in the event-log files were skipped");
        }
    }

    /** Activation body and test seam: sizes the ring and starts echoing entries to {@code sink}. */
    void start(IntSupplier capacity, Executor sinkExecutor, Consumer<EventEntry> sink) {
        configure(capacity);
        forwarder = new EventForwarder(ring, sinkExecutor, sink);
    }

    void configure(IntSupplier capacity) {
        ring.resize(Capacity.read("eventCapacity", capacity, ring.capacity()));
    }

    @Reference(name = "timeController", cardinality = ReferenceCardinality.OPTIONAL, policy = ReferencePolicy.DYNAMIC,
            policyOption = ReferencePolicyOption.GREEDY)
    void bindTimeController(TimeControllerProvider provider) {
        clock.use(provider);
    }

    void unbindTimeController(TimeControllerProvider provider) {
        clock.release(provider);
    }

    @Override
    public void record(EventKind kind, String origin, String message) {
        EventKind k = kind == null ? EventKind.PROBLEM : kind;
        Instant time = clock.now(); // outside the ring's lock: it may call the Time Controller
        ring.append(seq -> new EventEntry(seq, time, k, origin, message));
        history.signal();
        EventForwarder f = forwarder;
        if (f != null) {
            f.signal();
        }
    }

    @Override
    public List<EventEntry> recent(int max) {
        return ring.newest(max);
    }

    /** Searches the files (and what is not written yet); memory only: the ring. */
    @Override
    public LogHistory<EventEntry> query(LogQuery query) {
        return history.query(query::matches, query.limit());
    }

    /** @return the history on disk, or null when the log works in memory only */
    PersistentLog<EventEntry> persistent() {
        return history.history();
    }

    int capacity() {
        return ring.capacity();
    }
}

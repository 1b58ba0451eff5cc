package org.tinysep.runtime.internal.log;

import java.time.Clock;
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
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.LogQuery;
import org.tinysep.runtime.internal.RuntimeConfig;
import org.tinysep.runtime.internal.Threads;

/**
 * The platform's {@link EventLog}: a {@link LogService} of {@link EventLines}, kept on disk as {@code events-*.log}
 * and reloaded on start. {@link #record} is O(1) and does no I/O on the caller's thread; every entry is echoed to SLF4J logger {@code tinysep.events} at INFO
 * ({@code <kind> <origin> <message>}) from one background thread and written to the files from another.
 */
// name: the component name it had before the runtime was split into packages
@Component(name = "org.tinysep.runtime.internal.EventLogService",
        service = EventLog.class, configurationPid = RuntimeConfig.PID)
@Designate(ocd = RuntimeConfig.class)
public final class EventLogService extends LogService<EventEntry> implements EventLog {

    private static final Logger EVENTS = LoggerFactory.getLogger("tinysep.events");

    private volatile EventForwarder forwarder;
    private ExecutorService executor;

    public EventLogService() {
        this(Clock.systemUTC());
    }

    EventLogService(Clock fallback) {
        super(fallback, 10_000, new EventLines(), "events", "eventCapacity", LogQuery::matches, 0);
    }

    @Activate
    void activate(RuntimeConfig config, BundleContext context) {
        reconfigure(config::eventCapacity, LogConfig.read(config, context));
        executor = Executors.newSingleThreadExecutor(Threads.named("tinysep-event-log"));
        start(config::eventCapacity, executor, e -> EVENTS.info("{} {} {}", e.kind(), e.origin(), e.message()));
    }

    @Modified
    void modified(RuntimeConfig config, BundleContext context) {
        reconfigure(config::eventCapacity, LogConfig.read(config, context));
    }

    @Deactivate
    void deactivate() {
        forwarder = null;
        executor.shutdown(); // a pending drain still runs; nothing waits for it
        closeHistory();
    }

    /**
     * Keeps the history in files as {@code settings} say (null: memory only). Called before {@link #start} on
     * activation, it reloads the ring from the files; damaged lines are reported in the log itself.
     */
    @Override
    void persist(LogSettings settings) {
        long damaged = keep(settings);
        if (damaged > 0) {
            record(EventKind.PROBLEM, "event-log", damaged + " damaged lines in the event-log files were skipped");
        }
    }

    /** Activation body and test seam: sizes the ring and starts echoing entries to {@code sink}. */
    void start(IntSupplier capacity, Executor sinkExecutor, Consumer<EventEntry> sink) {
        configure(capacity);
        forwarder = new EventForwarder(ring(), sinkExecutor, sink);
    }

    @Override
    public void record(EventKind kind, String origin, String message) {
        EventKind k = kind == null ? EventKind.PROBLEM : kind;
        append((seq, time) -> new EventEntry(seq, time, k, origin, message));
        EventForwarder f = forwarder;
        if (f != null) {
            f.signal();
        }
    }
}

package org.tinysep.runtime.internal.log;

import java.time.Clock;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Consumer;
import java.util.function.IntSupplier;
import java.util.function.Predicate;
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
 * and reloaded on start. {@link #record} is O(1) and does no I/O on the caller's thread. Entries are echoed to SLF4J
 * logger {@code tinysep.events} ({@code <kind> <origin> <message>}) from one background thread — a device's events
 * ({@link EventKind#DEVICE_EVENT}, thousands a second on a busy radio) at DEBUG, every other kind at INFO — and
 * written to the files from another.
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
        start(config::eventCapacity, executor, EventLogService::echoed, EventLogService::echo);
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

    private static boolean echoed(EventEntry e) {
        return echoed(e.kind(), EVENTS);
    }

    /** @return whether {@link #echo} writes an entry of {@code kind} at {@code to}'s level (a device's events only at DEBUG) */
    static boolean echoed(EventKind kind, Logger to) {
        return kind == EventKind.DEVICE_EVENT ? to.isDebugEnabled() : to.isInfoEnabled();
    }

    private static void echo(EventEntry e) {
        if (e.kind() == EventKind.DEVICE_EVENT) {
            EVENTS.debug("{} {} {}", e.kind(), e.origin(), e.message());
        } else {
            EVENTS.info("{} {} {}", e.kind(), e.origin(), e.message());
        }
    }

    /** Test seam: sizes the ring and starts echoing every entry to {@code sink}. */
    void start(IntSupplier capacity, Executor sinkExecutor, Consumer<EventEntry> sink) {
        start(capacity, sinkExecutor, e -> true, sink);
    }

    /** Activation body: sizes the ring and starts echoing the entries {@code echoed} accepts to {@code sink}. */
    void start(IntSupplier capacity, Executor sinkExecutor, Predicate<EventEntry> echoed, Consumer<EventEntry> sink) {
        configure(capacity);
        forwarder = new EventForwarder(echoed, sinkExecutor, sink);
    }

    @Override
    public void record(EventKind kind, String origin, String message) {
        EventKind k = kind == null ? EventKind.PROBLEM : kind;
        EventEntry e = append((seq, time) -> new EventEntry(seq, time, k, origin, message));
        EventForwarder f = forwarder;
        if (f != null) {
            f.offer(e);
        }
    }
}

package org.tinysep.runtime.internal;

import java.time.Clock;
import java.time.Instant;
import java.util.List;
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
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.LogHistory;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.api.log.PacketLog;
import org.tinysep.api.service.TimeControllerProvider;

/**
 * The platform's {@link PacketLog}: an in-memory ring stamped with the platform time, kept on disk as
 * {@code packets-*.log} ({@link PersistentLog}) and reloaded on start. Bus radios call {@link #record} on their
 * receive threads at thousands of packets per second: it copies the bytes, takes a sequence number, stores a
 * reference and wakes the writer thread, O(1), no I/O. Configured from the same PID as the event log.
 */
@Component(service = PacketLog.class, configurationPid = RuntimeConfig.PID)
public final class PacketLogService implements PacketLog {

    private static final Logger LOG = LoggerFactory.getLogger(PacketLogService.class);

    private final PlatformClock clock;
    private final RingBuffer<PacketEntry> ring = new RingBuffer<>(20_000);
    private final HistoryKeeper<PacketEntry> history;

    public PacketLogService() {
        this(Clock.systemUTC());
    }

    PacketLogService(Clock fallback) {
        this.clock = new PlatformClock(fallback);
        this.history = new HistoryKeeper<>(ring, new PacketLines(), "packets", Clock.systemUTC());
    }

    @Activate
    @Modified
    void configure(RuntimeConfig config, BundleContext context) {
        configure(config::packetCapacity);
        persist(LogConfig.read(config, context));
    }

    @Deactivate
    void deactivate() {
        history.close(); // writes what is left and forces it to the disk
    }

    void configure(IntSupplier capacity) {
        ring.resize(Capacity.read("packetCapacity", capacity, ring.capacity()));
    }

    /** Keeps the history in files as {@code settings} say (null: memory only); the first call reloads the ring. */
    void persist(LogSettings settings) {
        long damaged = history.apply(settings);
        if (damaged > 0) {
            LOG.warn("{} damaged lines in the packet-log files were skipped", damaged);
        }
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
    public void record(Direction direction, String origin, byte[] bytes, String note) {
        Direction d = direction == null ? Direction.RECEIVED : direction;
        Instant time = clock.now(); // outside the ring's lock: it may call the Time Controller
        ring.append(seq -> new PacketEntry(seq, time, d, origin, bytes, note));
        history.signal();
    }

    @Override
    public List<PacketEntry> recent(int max) {
        return ring.newest(max);
    }

    /** Searches the files (and what is not written yet); memory only: the ring. */
    @Override
    public LogHistory<PacketEntry> query(LogQuery query) {
        return history.query(query::matches, query.limit());
    }

    /** @return the history on disk, or null when the log works in memory only */
    PersistentLog<PacketEntry> persistent() {
        return history.history();
    }

    int capacity() {
        return ring.capacity();
    }
}

package org.tinysep.runtime.internal.log;

import java.time.Clock;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Modified;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.LogQuery;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.api.log.PacketLog;
import org.tinysep.runtime.internal.RuntimeConfig;

/**
 * The platform's {@link PacketLog}: a {@link LogService} of {@link PacketLines}, kept on disk as
 * {@code packets-*.log}. Bus radios call {@link #record} on their receive threads at thousands of packets per
 * second: it copies the bytes, takes a sequence number, stores a reference and wakes the writer thread, O(1), no
 * I/O. Configured from the same PID as the event log.
 */
// name: the component name it had before the runtime was split into packages
@Component(name = "org.tinysep.runtime.internal.PacketLogService",
        service = PacketLog.class, configurationPid = RuntimeConfig.PID)
public final class PacketLogService extends LogService<PacketEntry> implements PacketLog {

    private static final Logger LOG = LoggerFactory.getLogger(PacketLogService.class);
    /**
     * The packet writer's beat while packets come: the receive thread hands the writer nothing per packet, and a
     * trickle of frames goes to the file in one write per beat. The price: a {@code kill -9} can lose the last
     * beat of packets (the event log keeps its 50 ms).
     */
    static final long BEAT_MILLIS = 500;

    public PacketLogService() {
        this(Clock.systemUTC());
    }

    PacketLogService(Clock fallback) {
        super(fallback, 20_000, new PacketLines(), "packets", "packetCapacity", LogQuery::matches, BEAT_MILLIS);
    }

    @Activate
    @Modified
    void configure(RuntimeConfig config, BundleContext context) {
        reconfigure(config::packetCapacity, LogConfig.read(config, context));
    }

    @Deactivate
    void deactivate() {
        closeHistory();
    }

    /** Keeps the history in files as {@code settings} say (null: memory only); the first call reloads the ring. */
    @Override
    void persist(LogSettings settings) {
        long damaged = keep(settings);
        if (damaged > 0) {
            LOG.warn("{} damaged lines in the packet-log files were skipped", damaged);
        }
    }

    @Override
    public void record(Direction direction, String origin, byte[] bytes, String note) {
        Direction d = direction == null ? Direction.RECEIVED : direction;
        append((seq, time) -> new PacketEntry(seq, time, d, origin, bytes, note));
    }
}

package org.tinysep.runtime.internal;

import java.time.Clock;
import java.time.Instant;
import java.util.List;
import java.util.function.IntSupplier;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Modified;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.api.log.PacketLog;
import org.tinysep.api.service.TimeControllerProvider;

/**
 * The platform's {@link PacketLog}: an in-memory ring stamped with the platform time. Bus radios call
 * {@link #record} on their receive threads at thousands of packets per second: it copies the bytes, takes a
 * sequence number and stores a reference, O(1), no I/O. Configured from the same PID as the event log.
 */
@Component(service = PacketLog.class, configurationPid = RuntimeConfig.PID)
public final class PacketLogService implements PacketLog {

    private final PlatformClock clock;
    private final RingBuffer<PacketEntry> ring = new RingBuffer<>(20_000);

    public PacketLogService() {
        this(Clock.systemUTC());
    }

    PacketLogService(Clock fallback) {
        this.clock = new PlatformClock(fallback);
    }

    @Activate
    @Modified
    void configure(RuntimeConfig config) {
        configure(config::packetCapacity);
    }

    void configure(IntSupplier capacity) {
        ring.resize(Capacity.read("packetCapacity", capacity, ring.capacity()));
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
    }

    @Override
    public List<PacketEntry> recent(int max) {
        return ring.newest(max);
    }

    int capacity() {
        return ring.capacity();
    }
}

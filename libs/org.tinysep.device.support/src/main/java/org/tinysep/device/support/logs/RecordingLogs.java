package org.tinysep.device.support.logs;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.api.log.PacketLog;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Unbounded in-memory event and packet logs, for tests and tools that run devices without a framework (see
 * {@link DriverContext#DriverContext(org.osgi.framework.BundleContext, String, String, Reporter, PlatformClock)}).
 * Not for production: the device manager's logs are bounded.
 */
public final class RecordingLogs {

    private final Supplier<Instant> clock;
    private final List<EventEntry> events = new ArrayList<>();
    private final List<PacketEntry> packets = new ArrayList<>();

    public RecordingLogs(Supplier<Instant> clock) {
        this.clock = clock;
    }

    /** @return a reporter writing into these logs */
    public Reporter reporter() {
        EventLog e = new EventLog() {
            @Override
            public void record(EventKind kind, String origin, String message) {
                addEvent(kind, origin, message);
            }

            @Override
            public List<EventEntry> recent(int max) {
                List<EventEntry> all = events();
                return all.subList(Math.max(0, all.size() - max), all.size());
            }
        };
        PacketLog p = new PacketLog() {
            @Override
            public void record(Direction direction, String origin, byte[] bytes, String note) {
                addPacket(direction, origin, bytes, note);
            }

            @Override
            public List<PacketEntry> recent(int max) {
                List<PacketEntry> all = packets();
                return all.subList(Math.max(0, all.size() - max), all.size());
            }
        };
        return new Reporter(() -> e, () -> p);
    }

    private synchronized void addEvent(EventKind kind, String origin, String message) {
        events.add(new EventEntry(events.size() + 1L, clock.get(), kind, origin, message));
    }

    private synchronized void addPacket(Direction direction, String origin, byte[] bytes, String note) {
        packets.add(new PacketEntry(packets.size() + 1L, clock.get(), direction, origin, bytes, note));
    }


    /** @return every event so far */
    public synchronized List<EventEntry> events() {
        return List.copyOf(events);
    }

    /** @return every packet so far */
    public synchronized List<PacketEntry> packets() {
        return List.copyOf(packets);
    }
}

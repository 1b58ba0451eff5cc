package org.tinysep.device.support.logs;

import java.util.function.Supplier;
import org.osgi.framework.BundleContext;
import org.osgi.util.tracker.ServiceTracker;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.PacketLog;

/**
 * Reports events and packets to the device manager's logs when they are present; without them, events go to
 * SLF4J only and packets are dropped. Never throws.
 */
public final class Reporter implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(Reporter.class);

    private final Supplier<EventLog> events;
    private final Supplier<PacketLog> packets;
    private final Runnable onClose;

    /** A reporter with explicit sinks (either may supply null); for tests and tools outside a framework. */
    public Reporter(Supplier<EventLog> events, Supplier<PacketLog> packets) {
        this(events, packets, () -> { });
    }

    private Reporter(Supplier<EventLog> events, Supplier<PacketLog> packets, Runnable onClose) {
        this.events = events;
        this.packets = packets;
        this.onClose = onClose;
    }

    /** A reporter that follows the EventLog and PacketLog services as they come and go. */
    public static Reporter tracking(BundleContext context) {
        ServiceTracker<EventLog, EventLog> e = new ServiceTracker<>(context, EventLog.class, null);
        ServiceTracker<PacketLog, PacketLog> p = new ServiceTracker<>(context, PacketLog.class, null);
        e.open();
        p.open();
        return new Reporter(e::getService, p::getService, () -> {
            e.close();
            p.close();
        });
    }

    /** Records one event-log entry. */
    public void event(EventKind kind, String origin, String message) {
        EventLog log = events.get();
        if (log == null) {
            LOG.info("{} {}: {}", kind, origin, message);
            return;
        }
        try {
            log.record(kind, origin, message);
        } catch (RuntimeException e) {
            LOG.warn("Event log refused an entry from {}: {}", origin, e.toString());
        }
    }

    /** Records one packet-log entry. */
    public void packet(Direction direction, String origin, byte[] bytes, String note) {
        PacketLog log = packets.get();
        if (log == null) {
            return;
        }
        try {
            log.record(direction, origin, bytes, note);
        } catch (RuntimeException e) {
            LOG.warn("Packet log refused an entry from {}: {}", origin, e.toString());
        }
    }

    @Override
    public void close() {
        onClose.run();
    }
}

package org.tinysep.device.support;

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

    private final ServiceTracker<EventLog, EventLog> events;
    private final ServiceTracker<PacketLog, PacketLog> packets;

    public Reporter(BundleContext context) {
        events = new ServiceTracker<>(context, EventLog.class, null);
        packets = new ServiceTracker<>(context, PacketLog.class, null);
        events.open();
        packets.open();
    }

    /** Records one event-log entry. */
    public void event(EventKind kind, String origin, String message) {
        EventLog log = events.getService();
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
        PacketLog log = packets.getService();
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
        events.close();
        packets.close();
    }
}

package org.tinysep.inactivity.internal;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.LongSupplier;
import org.tinysep.device.support.rooms.Placements;

/**
 * The "room" of a device without one, "unknown room (device Hall sensor)", looked up at most once per device per
 * {@link #REFRESH_NANOS} (a rename shows within that time). A look-up per activity would cost a service-registry
 * look-up of the device's name and a new string, which the learned limits' cache would hash anew; instead the same
 * string is handed out until the next look-up. Thread-safe.
 */
final class UnplacedNames {

    /** How long a looked-up name is reused. */
    static final long REFRESH_NANOS = 10_000_000_000L;
    /** More unplaced devices than this: start afresh (bounded memory). */
    static final int MAX_DEVICES = 4_096;

    private record Named(String roomName, long lookedUpAt) {
    }

    private final Placements directory;
    private final LongSupplier nanos;
    private final Map<String, Named> names = new ConcurrentHashMap<>();

    UnplacedNames(Placements directory) {
        this(directory, System::nanoTime);
    }

    /** @param nanos a monotonic clock in nanoseconds */
    UnplacedNames(Placements directory, LongSupplier nanos) {
        this.directory = directory;
        this.nanos = nanos;
    }

    /** @return "unknown room (device NAME)" for the device {@code deviceUid}, which has no room */
    String nameOf(String deviceUid) {
        long now = nanos.getAsLong();
        Named n = names.get(deviceUid);
        if (n == null || now - n.lookedUpAt() >= REFRESH_NANOS) {
            String roomName = "unknown room (device " + directory.nameOf(deviceUid) + ")";
            n = new Named(n != null && n.roomName().equals(roomName) ? n.roomName() : roomName, now);
            if (names.size() >= MAX_DEVICES) {
                names.clear();
            }
            names.put(deviceUid, n);
        }
        return n.roomName();
    }
}

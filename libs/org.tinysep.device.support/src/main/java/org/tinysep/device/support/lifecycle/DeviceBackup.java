package org.tinysep.device.support.lifecycle;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.LongSupplier;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.backup.ComponentKind;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;

/**
 * A device's side of the system backup (thesis 3.7): builds its {@link ComponentBackup} (name, room, the writable
 * parameters it keeps, node address and types, last seen time, free state), saves it, and throttles saves of
 * runtime state to one per {@link #STATE_INTERVAL_NANOS}. Runtime state is saved only when it changes
 * what a restart needs; the last seen time alone (every frame of a movement sensor moves it) is saved at most once
 * per {@link #LAST_SEEN_INTERVAL_NANOS} (an orderly stop saves the exact one), so a busy sensor no longer costs a
 * JAXB write and an fsync every 10 s. A backup equal to the one last saved (or restored), its save time aside, is
 * not written again: a device restored and activated unchanged, or stopped unchanged, costs no write (issue 29:
 * stopping and restarting 20,000 devices wrote 20,000 files each time).
 */
final class DeviceBackup {

    /** Runtime state (e.g. a node's last seen time) is saved at most this often per device: 10 s. */
    static final long STATE_INTERVAL_NANOS = 10_000_000_000L;
    /** When only the last seen time moved, it is saved at most this often per device: 60 s. */
    static final long LAST_SEEN_INTERVAL_NANOS = 60_000_000_000L;

    private final AbstractDevice device;
    private volatile LongSupplier nanos = System::nanoTime;
    private volatile long lastStateSave = System.nanoTime() - STATE_INTERVAL_NANOS;
    private volatile long lastSave = lastStateSave;
    /** The backup last saved or restored (the file's content, save time aside); null when none or it failed. */
    private final AtomicReference<ComponentBackup> saved = new AtomicReference<>();
    private volatile boolean active;

    DeviceBackup(AbstractDevice device) {
        this.device = device;
    }

    /** Tests: the monotonic clock of the throttles. */
    void nanos(LongSupplier clock) {
        nanos = clock;
        lastStateSave = clock.getAsLong() - STATE_INTERVAL_NANOS;
        lastSave = lastStateSave;
    }

    /** @return the device's backup as of now: name, room, kept writable parameters, node, state */
    ComponentBackup snapshot(DeviceParameters settings, DeviceRegistration registration) {
        DriverContext c = device.context;
        Map<String, String> parameters = new LinkedHashMap<>();
        String roomUid = settings.savedRoomUid();
        if (roomUid != null) {
            parameters.put(RoomPlacement.KEY, roomUid);
        }
        for (Parameter p : settings.list()) {
            if (p.writable() && !p.key().equals(DeviceParameters.NAME) && !p.key().equals(RoomPlacement.KEY)
                    && device.backedUp(p.key()) && p.value() != null && !p.value().isBlank()) {
                parameters.put(p.key(), p.value());
            }
        }
        Object nodeAddress = registration.property(DeviceProperties.NODE_ADDRESS);
        Object nodeTypes = registration.property(DeviceProperties.NODE_TYPE);
        List<String> types = nodeTypes instanceof String[] a ? Arrays.asList(a)
                : nodeTypes == null ? List.of() : List.of(String.valueOf(nodeTypes));
        return new ComponentBackup(device.uid(), ComponentKind.DEVICE, c.driverUid(), c.driverName(), device.type(),
                device.name(), parameters, nodeAddress == null ? "" : String.valueOf(nodeAddress), types,
                device.lastSeen(), device.backupState(), c.now());
    }

    /**
     * From now on changes are saved (after the device registered, with its restored settings); saved now unless
     * the backup it was restored from already says the same.
     */
    void activate() {
        active = true;
        storeIfChanged(device.backup());
    }

    void deactivate() {
        active = false;
    }

    boolean active() {
        return active;
    }

    /** Saves now, without waiting for the disk, unless nothing changed since the last save. */
    void save() {
        if (active) {
            storeIfChanged(device.backup());
        }
    }

    private void storeIfChanged(ComponentBackup b) {
        ComponentBackup before = saved.get();
        if (before != null && sameForRestart(before, b) && Objects.equals(before.lastSeen(), b.lastSeen())) {
            return; // the file on disk (or queued) already holds this
        }
        store(b);
    }

    /**
     * Runtime state changed: looked at once per 10 s per device (cheap to call on every packet), saved then if
     * anything but the last seen time changed since the last save, or the last save is 60 s old.
     */
    void stateChanged() {
        long now = nanos.getAsLong();
        if (!active || now - lastStateSave < STATE_INTERVAL_NANOS) {
            return;
        }
        lastStateSave = now;
        ComponentBackup b = device.backup();
        ComponentBackup before = saved.get();
        if (before != null && sameForRestart(before, b)
                && (now - lastSave < LAST_SEEN_INTERVAL_NANOS || Objects.equals(before.lastSeen(), b.lastSeen()))) {
            return; // only the last seen time moved: it waits (an orderly stop saves it exactly)
        }
        store(b);
    }

    private void store(ComponentBackup b) {
        saved.set(b);
        lastSave = nanos.getAsLong();
        device.context.backups().save(b).whenComplete((done, failed) -> {
            if (failed != null) {
                saved.compareAndSet(b, null); // not on disk: the next save writes again
            }
        });
    }

    /** @return whether a restart would restore the same device from both (their last seen and saved times aside) */
    static boolean sameForRestart(ComponentBackup a, ComponentBackup b) {
        return a.uid().equals(b.uid()) && a.kind() == b.kind() && a.driverUid().equals(b.driverUid())
                && a.driverName().equals(b.driverName()) && a.type().equals(b.type()) && a.name().equals(b.name())
                && a.parameters().equals(b.parameters()) && a.nodeAddress().equals(b.nodeAddress())
                && a.nodeTypes().equals(b.nodeTypes()) && a.state().equals(b.state());
    }

    /** Applies a saved backup to a device that is not registered yet: name, settings, then its own state. */
    void restore(ComponentBackup b, DeviceParameters settings) {
        saved.set(b); // what the file holds: activating the device unchanged writes nothing
        settings.restoreName(b.name());
        for (Map.Entry<String, String> e : b.parameters().entrySet()) {
            String key = e.getKey();
            try {
                if (RoomPlacement.KEY.equals(key)) {
                    settings.restoreRoom(e.getValue());
                } else if (!DeviceProperties.ROOM.equals(key)) {
                    device.applyParameter(key, e.getValue());
                }
            } catch (RuntimeException ex) {
                device.context.reporter().event(EventKind.PROBLEM, device.uid(), "saved setting " + key + "="
                        + e.getValue() + " not restored: " + ex.getMessage());
            }
        }
        device.onRestore(b);
    }
}

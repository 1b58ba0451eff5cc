package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import org.junit.jupiter.api.Test;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.rooms.RoomDirectory;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Issue 29, item 1: a busy sensor's runtime state is saved only when it changes what a restart needs; the last
 * seen time alone at most once per 60 s (it was every 10 s: a JAXB write and an fsync each).
 */
class DeviceStateSavesTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    /** A node's device: every frame moves its last seen time; {@code battery} is state a restart needs. */
    private static final class Sensor extends AbstractDevice {
        volatile Instant lastSeen = T0;
        volatile String battery = "3000";

        Sensor(DriverContext c) {
            super(c, "dev-1", "Sensor", "Sensor 1");
        }

        @Override
        protected Instant lastSeen() {
            return lastSeen;
        }

        @Override
        protected Map<String, String> backupState() {
            return Map.of("batteryMillivolts", battery);
        }

        void frame(Instant at) {
            lastSeen = at;
            stateChanged();
        }
    }

    /** Counts the saves (each one a JAXB write and an fsync in the real store). */
    private static final class Store implements BackupStore {
        final List<ComponentBackup> saved = new ArrayList<>();

        @Override
        public CompletionStage<Void> save(ComponentBackup backup) {
            saved.add(backup);
            return CompletableFuture.completedFuture(null);
        }

        @Override
        public boolean flush(Duration timeout) {
            return true;
        }

        @Override
        public Optional<ComponentBackup> find(String uid) {
            return Optional.empty();
        }

        @Override
        public List<ComponentBackup> devicesOf(String driverUid) {
            return List.of();
        }

        @Override
        public void delete(String uid) {
        }
    }

    private final Store store = new Store();
    private long nanos;

    private Sensor sensor() {
        Sensor s = new Sensor(new DriverContext(null, "drv", "AmicaMovement", new RecordingLogs(() -> T0).reporter(),
                new PlatformClock(() -> T0), RoomDirectory.of(new FakeHouse()), Backups.of(store)));
        s.backupSide().nanos(() -> nanos);
        s.backupSide().activate();
        return s;
    }

    @Test
    void framesThatMoveOnlyTheLastSeenTimeAreSavedOncePerMinute() {
        Sensor s = sensor();
        for (int i = 1; i <= 300; i++) { // 10 minutes, one frame every 2 s
            nanos += 2_000_000_000L;
            s.frame(T0.plusSeconds(2L * i));
        }
        int saves = store.saved.size();
        assertTrue(saves >= 1 + 9 && saves <= 1 + 10, "the activation's save and one per minute over 10 minutes: "
                + saves + " saves for 300 frames");
        Instant last = store.saved.get(saves - 1).lastSeen();
        assertTrue(!last.isBefore(T0.plusSeconds(600 - 60)), "the saved last seen time is at most a minute old: "
                + last);
    }

    @Test
    void stateARestartNeedsIsSavedWithinTenSeconds() {
        Sensor s = sensor();
        nanos += 11_000_000_000L;
        s.frame(T0.plusSeconds(11));
        int before = store.saved.size();
        s.battery = "2900";
        nanos += 1_000_000_000L;
        s.frame(T0.plusSeconds(12)); // within 10 s of the last look: waits
        assertEquals(before, store.saved.size());
        nanos += 10_000_000_000L;
        s.frame(T0.plusSeconds(22));
        assertEquals(before + 1, store.saved.size());
        assertEquals("2900", store.saved.get(before).state().get("batteryMillivolts"));
    }
}

package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.rooms.RoomDirectory;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Issue 29, item 4: an orderly stop and a restart write only the backups that changed. Stopping 20,000 unchanged
 * devices wrote 20,000 files (JAXB and a group fsync each batch), and the restart wrote them all again as each
 * restored device activated; both now write none, at n and at 2n devices, and a changed device is still saved.
 */
class StopAndRestartSavesTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    /** A node's device with a last seen time and state a restart needs, both restored from its backup. */
    private static final class Sensor extends AbstractDevice {
        volatile Instant lastSeen = T0;
        volatile String battery = "3000";

        Sensor(DriverContext c, int i) {
            super(c, "dev-" + i, "Sensor", "Sensor " + i);
        }

        @Override
        protected Instant lastSeen() {
            return lastSeen;
        }

        @Override
        protected Map<String, String> backupState() {
            return Map.of("batteryMillivolts", battery);
        }

        @Override
        protected void onRestore(ComponentBackup saved) {
            lastSeen = saved.lastSeen();
            battery = saved.state().get("batteryMillivolts");
        }
    }

    /** The store: counts the saves (each one a JAXB write and part of an fsync batch in the real one). */
    private static final class Store implements BackupStore {
        final List<ComponentBackup> saved = new ArrayList<>();
        volatile boolean failing;

        @Override
        public CompletionStage<Void> save(ComponentBackup backup) {
            saved.add(backup);
            return failing ? CompletableFuture.failedFuture(new IllegalStateException("disk full"))
                    : CompletableFuture.completedFuture(null);
        }

        @Override
        public boolean flush(Duration timeout) {
            return true;
        }

        @Override
        public Optional<ComponentBackup> find(String uid) {
            return saved.stream().filter(b -> b.uid().equals(uid)).reduce((a, b) -> b);
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

    private DriverContext context() {
        return new DriverContext(null, "drv", "AmicaMovement", new RecordingLogs(() -> T0).reporter(),
                new PlatformClock(() -> T0), RoomDirectory.of(new FakeHouse()), Backups.of(store));
    }

    /** A device as its driver makes it: restored from its backup if there is one, then activated. */
    private Sensor start(DriverContext c, int i) {
        Sensor s = new Sensor(c, i);
        store.find(s.uid()).ifPresent(s::restore);
        s.backupSide().activate();
        return s;
    }

    @ParameterizedTest
    @ValueSource(ints = {1_000, 2_000})
    void aStopAndARestartOfUnchangedDevicesWriteNothing(int n) {
        DriverContext c = context();
        List<Sensor> first = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            first.add(start(c, i));
        }
        assertEquals(n, store.saved.size(), "each new device is saved once");
        first.forEach(AbstractDevice::dispose); // the orderly stop
        assertEquals(n, store.saved.size(), "saves by the stop of " + n + " unchanged devices");
        List<Sensor> again = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            again.add(start(c, i)); // the restart: each restored from its backup
        }
        assertEquals(n, store.saved.size(), "saves by the restart of " + n + " devices restored unchanged");
        again.forEach(AbstractDevice::dispose);
        assertEquals(n, store.saved.size(), "saves by the second stop");
    }

    @ParameterizedTest
    @ValueSource(ints = {1_000, 2_000})
    void theStopSavesExactlyTheDevicesThatChanged(int n) {
        DriverContext c = context();
        List<Sensor> all = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            all.add(start(c, i));
        }
        int before = store.saved.size();
        for (int i = 0; i < n; i += 2) {
            all.get(i).lastSeen = T0.plusSeconds(5); // heard from since the last save (not saved yet: throttled)
        }
        all.get(1).battery = "2900";
        all.forEach(AbstractDevice::dispose);
        List<ComponentBackup> atStop = store.saved.subList(before, store.saved.size());
        assertEquals(n / 2 + 1, atStop.size(), "the moved last seen times and the one changed battery");
        assertEquals(T0.plusSeconds(5), store.find("dev-0").orElseThrow().lastSeen(), "the exact last seen time");
        assertEquals("2900", store.find("dev-1").orElseThrow().state().get("batteryMillivolts"));
    }

    @Test
    void aSaveThatFailedIsWrittenAgainAtTheStop() {
        store.failing = true;
        Sensor s = start(context(), 0);
        store.failing = false;
        s.dispose();
        assertEquals(2, store.saved.size(), "the failed save is not taken for one on disk");
    }
}

package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.tinysep.api.backup.ComponentBackup;

/**
 * Issue 29, item 4: an orderly stop and a restart write only the backups that changed. Stopping 20,000 unchanged
 * devices wrote 20,000 files (JAXB and a group fsync each batch), and the restart wrote them all again as each
 * restored device activated; both now write none, at n and at 2n devices, and a changed device is still saved.
 */
class StopAndRestartSavesTest {

    private static final Instant T0 = SavedSensor.T0;

    private final CountingStore store = new CountingStore();

    private DriverContext context() {
        return SavedSensor.context(store);
    }

    /** A device as its driver makes it: restored from its backup if there is one, then activated. */
    private SavedSensor start(DriverContext c, int i) {
        SavedSensor s = new SavedSensor(c, i);
        store.find(s.uid()).ifPresent(s::restore);
        s.backupSide().activate();
        return s;
    }

    @ParameterizedTest
    @ValueSource(ints = {1_000, 2_000})
    void aStopAndARestartOfUnchangedDevicesWriteNothing(int n) {
        DriverContext c = context();
        List<SavedSensor> first = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            first.add(start(c, i));
        }
        assertEquals(n, store.saved.size(), "each new device is saved once");
        first.forEach(AbstractDevice::dispose); // the orderly stop
        assertEquals(n, store.saved.size(), "saves by the stop of " + n + " unchanged devices");
        List<SavedSensor> again = new ArrayList<>();
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
        List<SavedSensor> all = new ArrayList<>();
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
        SavedSensor s = start(context(), 0);
        store.failing = false;
        s.dispose();
        assertEquals(2, store.saved.size(), "the failed save is not taken for one on disk");
    }
}

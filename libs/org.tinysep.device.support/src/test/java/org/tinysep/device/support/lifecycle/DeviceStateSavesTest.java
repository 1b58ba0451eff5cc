package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import org.junit.jupiter.api.Test;

/**
 * Issue 29, item 1: a busy sensor's runtime state is saved only when it changes what a restart needs; the last
 * seen time alone at most once per 60 s (it was every 10 s: a JAXB write and an fsync each).
 */
class DeviceStateSavesTest {

    private static final Instant T0 = SavedSensor.T0;

    private final CountingStore store = new CountingStore();
    private long nanos;

    private SavedSensor sensor() {
        SavedSensor s = new SavedSensor(SavedSensor.context(store), 1);
        s.backupSide().nanos(() -> nanos);
        s.backupSide().activate();
        return s;
    }

    @Test
    void framesThatMoveOnlyTheLastSeenTimeAreSavedOncePerMinute() {
        SavedSensor s = sensor();
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
        SavedSensor s = sensor();
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

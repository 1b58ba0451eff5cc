package org.tinysep.device.support.lifecycle;

import java.time.Instant;
import java.util.Map;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.rooms.RoomDirectory;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.time.PlatformClock;

/**
 * A node's device for the save-counting tests: every frame moves its last seen time; {@code battery} is state a
 * restart needs; both are restored from its backup.
 */
final class SavedSensor extends AbstractDevice {

    static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    volatile Instant lastSeen = T0;
    volatile String battery = "3000";

    SavedSensor(DriverContext c, int i) {
        super(c, "dev-" + i, "Sensor", "Sensor " + i);
    }

    /** A driver's context at {@link #T0} whose backups go to {@code store}. */
    static DriverContext context(CountingStore store) {
        return new DriverContext(null, "drv", "AmicaMovement", new RecordingLogs(() -> T0).reporter(),
                new PlatformClock(() -> T0), RoomDirectory.of(new FakeHouse()), Backups.of(store));
    }

    void frame(Instant at) {
        lastSeen = at;
        stateChanged();
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

package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.backup.ComponentKind;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.rooms.RoomDirectory;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.time.PlatformClock;

/** A device's backup (docs/backup.md): what the snapshot holds and how a saved one is applied. */
class DeviceBackupTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    /** A device with one setting ({@code kind}) and one command ({@code level}). */
    private static final class Door extends AbstractDevice {
        String kind = "OUTER";
        String level = "";
        Map<String, String> restoredState;

        Door(DriverContext c) {
            super(c, "dev-1", "Door", "Door 1");
        }

        @Override
        protected List<Parameter> moreParameters() {
            return List.of(Parameter.writable("kind", kind, "OUTER or INNER"),
                    Parameter.writable("level", level, "a command"),
                    Parameter.readOnly("packets", 12, "a reading"));
        }

        @Override
        protected void applyParameter(String key, String value) {
            switch (key) {
                case "kind" -> {
                    if (!value.equals("OUTER") && !value.equals("INNER")) {
                        throw new IllegalArgumentException("kind must be OUTER or INNER");
                    }
                    kind = value;
                }
                case "level" -> level = value;
                default -> throw unknownParameter(key);
            }
        }

        @Override
        protected boolean backedUp(String key) {
            return !key.equals("level");
        }

        @Override
        protected Map<String, String> backupState() {
            return Map.of("opened", "3");
        }

        @Override
        protected void onRestore(ComponentBackup saved) {
            restoredState = saved.state();
        }
    }

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final FakeHouse house = new FakeHouse();
    private final Room bath = house.add("0cf52171-0d00-486f-bbb2-e6ef950012b5", "Bathroom");

    private DriverContext context() {
        return new DriverContext(null, "drv", "AmicaDoor", logs.reporter(), new PlatformClock(() -> T0),
                RoomDirectory.of(house));
    }

    @Test
    void theSnapshotHoldsNameRoomUidAndSettingsButNoCommandsOrReadings() {
        Door d = new Door(context());
        d.setParameter("name", "Front door");
        d.setParameter("room", "Bathroom");
        d.setParameter("kind", "INNER");
        d.setParameter("level", "40");
        ComponentBackup b = d.backup();
        assertEquals(new ComponentBackup("dev-1", ComponentKind.DEVICE, "drv", "AmicaDoor", "Door", "Front door",
                Map.of("room", bath.uid(), "kind", "INNER"), "", List.of(), null, Map.of("opened", "3"), T0), b);
        assertEquals(List.of("room", "kind"), List.copyOf(b.parameters().keySet()), "room first");
    }

    @Test
    void aSavedBackupIsAppliedAsItWasAndABadSettingIsReportedNotThrown() {
        Door d = new Door(context());
        d.restore(new ComponentBackup("dev-1", ComponentKind.DEVICE, "drv", "AmicaDoor", "Door", "Front door",
                Map.of("room", bath.uid(), "kind", "SIDEWAYS"), "", List.of(), null, Map.of("opened", "3"), T0));
        assertEquals("Front door", d.name());
        assertEquals("Bathroom (" + bath.uid() + ")", d.parameters().get(1).value());
        assertEquals("OUTER", d.kind, "the bad value is not applied");
        assertEquals(Map.of("opened", "3"), d.restoredState);
        assertTrue(logs.events().stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                && e.message().contains("kind=SIDEWAYS not restored")), () -> logs.events().toString());
    }

    @Test
    void aSavedRoomTheHouseNoLongerHasIsDropped() {
        Door d = new Door(context());
        d.restore(new ComponentBackup("dev-1", ComponentKind.DEVICE, "drv", "AmicaDoor", "Door", "Door 1",
                Map.of("room", "a-room-that-was-removed"), "", List.of(), null, Map.of(), T0));
        assertNull(d.backup().parameters().get("room"));
    }
}

package org.tinysep.runtime.internal.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Clock;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.runtime.internal.directory.DeviceDirectory;
import org.tinysep.runtime.internal.directory.DeviceRecord;
import org.tinysep.runtime.internal.directory.DriverRecord;
import org.tinysep.runtime.internal.directory.FakeDevice;
import org.tinysep.runtime.internal.directory.Home;
import org.tinysep.runtime.internal.directory.Inventory;
import org.tinysep.runtime.internal.directory.NodeInfo;

/** The shell output is a contract (integration tests parse it): these tests pin it character by character. */
class ShellCommandsTest {

    static final Clock CLOCK = Clock.fixed(Instant.parse("2026-11-22T11:10:00.123456Z"), ZoneOffset.UTC);

    private final Home home = new Home();
    private final ShellCommands shell = new ShellCommands(new Operations(home.directory, id -> "b" + id, 5));

    @Test
    void devicesListsOneBlockPerDeviceSortedByUid() {
        home.busDoor.status = new DeviceStatus(DeviceStatus.State.OFFLINE, "no packet for 300 s",
                Instant.parse("2026-01-01T00:00:00Z"));
        String expected = String.join("\n",
                "amica-movement-0012 AmicaMovement \"Movement 0012\" [ONLINE] driver=AmicaMovement",
                "  provides: MovementProvider, MovementWithCoordinatesProvider",
                "  connected to: BusRadioAmicaProvider <- amica-node-0012 (vital)",
                "  node: types=movement, address=0012, room=kitchen",
                "  parameters: timeout=30, events=4",
                "  functions: reset",
                "amica-node-0012 BusRadioAmica \"AmICA node 0012\" [ONLINE] driver=BusRadioAmica",
                "  provides: BusRadioAmicaProvider",
                "  connected to: -",
                "  node: types=movement, address=0012, room=kitchen",
                "  parameters: rssi=-61",
                "amica-node-0013 BusRadioAmica \"AmICA node 0013\" [OFFLINE (no packet for 300 s)] driver=BusRadioAmica",
                "  provides: BusRadioAmicaProvider",
                "  connected to: -",
                "  node: types=door, address=0013",
                "  parameters: -",
                "flat-occupancy-1 FlatOccupancy \"Flat\" [ONLINE] driver=FlatOccupancy",
                "  provides: FlatOccupancyProvider",
                "  connected to: MovementProvider <- amica-movement-0012 (optional)",
                "  connected to: DoorProvider <- amica-door-0013 (optional)",
                "  parameters: -");
        assertEquals(expected, shell.devices());
    }

    @Test
    void aFailingDeviceIsShownWithErrorLinesAndTheOthersStillList() {
        home.flatOccupancy.failure = new IllegalStateException("not\nready");
        String out = shell.devices();
        String block = out.substring(out.indexOf("flat-occupancy-1 "));
        assertEquals(String.join("\n",
                "flat-occupancy-1 FlatOccupancy \"Flat\" [?] driver=FlatOccupancy",
                "  provides: FlatOccupancyProvider",
                "  connected to: -",
                "  parameters: -",
                "  error: name() failed: IllegalStateException: not ready",
                "  error: status() failed: IllegalStateException: not ready",
                "  error: connections() failed: IllegalStateException: not ready",
                "  error: parameters() failed: IllegalStateException: not ready",
                "  error: functions() failed: IllegalStateException: not ready"), block);
    }

    @Test
    void aDeviceOfAnUnknownDriverShowsTheDriverUid() {
        FakeDevice orphan = new FakeDevice("orphan-1", "Orphan", "gone", "Orphan");
        home.directory.put(new DeviceRecord(1, orphan.uid, orphan.type, orphan.name, orphan.driverUid,
                NodeInfo.NONE, orphan));
        String out = shell.devices();
        assertEquals("orphan-1 Orphan \"Orphan\" [ONLINE] driver=?gone", out.lines()
                .filter(l -> l.startsWith("orphan-1")).findFirst().orElseThrow());
    }

    @Test
    void driversIsATableSortedByName() {
        assertEquals(String.join("\n",
                "UID            | NAME          | BUNDLE | DEVICES | PARAMETERS",
                "amica-movement | AmicaMovement | 8      | 1       | -",
                "busradio-amica | BusRadioAmica | 7      | 2       | port=47001, rejected=2",
                "flat-occupancy | FlatOccupancy | 9      | 1       | -"), shell.drivers());
    }

    @Test
    void emptyInventorySaysSo() {
        ShellCommands empty = new ShellCommands(new Operations(new DeviceDirectory(), id -> "", 5));
        assertEquals("(no drivers)", empty.drivers());
        assertEquals("(no devices)", empty.devices());
    }

    @Test
    void errorsAreOneLineMessages() {
        assertEquals("no device matches 'nope-nope'",
                assertThrows(IllegalArgumentException.class, () -> shell.set("nope-nope", "k", "v")).getMessage());
        String message = assertThrows(IllegalArgumentException.class, () -> shell.remove("xyz")).getMessage();
        assertFalse(message.contains("\n"));
        assertEquals("amica-movement-0012: timeout=60", shell.set("amica-movement-0012", "timeout", "60"));
        assertEquals("amica-movement-0012 reset: did reset", shell.invoke("amica-movement-0012", "reset"));
    }

    @Test
    void unexpectedFailuresAreWrappedIntoAOneLineMessage() {
        Inventory broken = new Inventory() {
            @Override
            public List<DriverRecord> drivers() {
                throw new UnsupportedOperationException("inventory closed");
            }

            @Override
            public List<DeviceRecord> devices() {
                return List.of();
            }

            @Override
            public List<String> interfacesOf(String deviceUid) {
                return List.of();
            }
        };
        ShellCommands s = new ShellCommands(new Operations(broken, id -> "", 5));
        assertEquals("drivers failed: UnsupportedOperationException: inventory closed",
                assertThrows(IllegalStateException.class, s::drivers).getMessage());
    }
}

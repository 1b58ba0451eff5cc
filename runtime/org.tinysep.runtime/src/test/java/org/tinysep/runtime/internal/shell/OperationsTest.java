package org.tinysep.runtime.internal.shell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.osgi.framework.BundleException;
import org.tinysep.api.device.Parameter;
import org.tinysep.runtime.internal.directory.DeviceRecord;
import org.tinysep.runtime.internal.directory.DeviceView;
import org.tinysep.runtime.internal.directory.DriverRecord;
import org.tinysep.runtime.internal.directory.FakeDevice;
import org.tinysep.runtime.internal.directory.FakeDriver;
import org.tinysep.runtime.internal.directory.Home;
import org.tinysep.runtime.internal.directory.NodeInfo;

class OperationsTest {

    static final long OWN_BUNDLE = 5;

    private final Home home = new Home();
    private final List<Long> stopped = new ArrayList<>();
    private final Operations ops = new Operations(home.directory, id -> {
        stopped.add(id);
        return "bundle." + id;
    }, OWN_BUNDLE);

    @Test
    void removeDeviceAsksTheOwningDriverOnly() {
        String result = ops.removeDevice("amica-movement-0012");
        assertEquals("removed device amica-movement-0012 (AmicaMovement) of driver AmicaMovement", result);
        assertEquals(List.of("amica-movement-0012"), home.movement.removeCalls);
        assertTrue(home.bus.removeCalls.isEmpty());
        assertTrue(home.flat.removeCalls.isEmpty());
    }

    @Test
    void removeDeviceAcceptsAUniquePrefix() {
        ops.removeDevice("amica-node-0013");
        ops.removeDevice("flat-occ");
        assertEquals(List.of("amica-node-0013"), home.bus.removeCalls);
        assertEquals(List.of("flat-occupancy-1"), home.flat.removeCalls);
    }

    @Test
    void removeDeviceReportsADriverThatRefusesOrIsMissing() {
        home.movement.devices.clear(); // the driver no longer knows the device
        IllegalStateException refused = assertThrows(IllegalStateException.class,
                () -> ops.removeDevice("amica-movement-0012"));
        assertEquals("driver AmicaMovement says device amica-movement-0012 is not one of its devices; nothing removed",
                refused.getMessage());

        FakeDevice orphan = new FakeDevice("orphan-0001", "Orphan", "gone-driver", "Orphan");
        home.directory.put(new DeviceRecord(999, orphan.uid, orphan.type, orphan.name, orphan.driverUid,
                NodeInfo.NONE, orphan));
        IllegalStateException missing = assertThrows(IllegalStateException.class, () -> ops.removeDevice("orph"));
        assertEquals("device orphan-0001 belongs to driver uid 'gone-driver', which is not registered",
                missing.getMessage());
    }

    @Test
    void removeRoutesToDeviceOrDriver() {
        ops.remove("amica-node-0012");
        assertEquals(List.of("amica-node-0012"), home.bus.removeCalls);
        assertEquals("stopped bundle 8 (bundle.8): driver AmicaMovement and its devices removed; "
                + "'start 8' brings them back", ops.remove("AmicaMovement"));
        ops.remove("busradio-amica");
        ops.remove("flat-occupancy-1");
        assertEquals(List.of(8L, 7L), stopped);
        assertEquals(List.of("flat-occupancy-1"), home.flat.removeCalls, "exact device uid before driver prefix");
    }

    @Test
    void removeComplainsClearlyWhenNothingOrSeveralMatch() {
        IllegalArgumentException none = assertThrows(IllegalArgumentException.class, () -> ops.remove("heater-7"));
        assertEquals("no device or driver matches 'heater-7' (give a device uid or a unique prefix of at least 4 "
                + "characters, or a driver uid or name)", none.getMessage());
        IllegalArgumentException several = assertThrows(IllegalArgumentException.class, () -> ops.remove("amica-mo"));
        assertEquals("'amica-mo' is ambiguous: it matches 2 (amica-movement-0012, amica-movement); "
                + "give more characters", several.getMessage());
        assertTrue(stopped.isEmpty());
        assertTrue(home.movement.removeCalls.isEmpty());
    }

    @Test
    void removeDriverRefusesTheDeviceManagerItselfAndReportsStopFailures() {
        FakeDriver own = new FakeDriver("self", "Self");
        home.directory.put(new DriverRecord(500, own.uid, own.name, OWN_BUNDLE, "org.tinysep.runtime", own));
        assertEquals("driver Self is registered by bundle 5 (org.tinysep.runtime), which cannot be stopped from here",
                assertThrows(IllegalArgumentException.class, () -> ops.removeDriver("Self")).getMessage());

        Operations failing = new Operations(home.directory, id -> {
            throw new BundleException("Cannot acquire global lock");
        }, OWN_BUNDLE);
        assertEquals("could not stop bundle 9 (org.tinysep.flatoccupancy) of driver FlatOccupancy: "
                + "BundleException: Cannot acquire global lock",
                assertThrows(IllegalStateException.class, () -> failing.removeDriver("flatoccupancy")).getMessage());
    }

    @Test
    void setParameterChangesTheDeviceAndReportsRejectionsClearly() {
        assertEquals("amica-movement-0012: timeout=45", ops.setParameter("amica-movement-0012", "timeout", "45"));
        assertEquals("45", home.amicaMovement.parameters.get("timeout").value());

        assertEquals("cannot set timeout on amica-movement-0012: timeout must be a whole number of seconds, not 'soon'",
                assertThrows(IllegalArgumentException.class,
                        () -> ops.setParameter("amica-movement", "timeout", "soon")).getMessage());
        assertEquals("cannot set events on amica-movement-0012: events is read-only",
                assertThrows(IllegalArgumentException.class,
                        () -> ops.setParameter("amica-movement", "events", "0")).getMessage());
        assertEquals("cannot set colour on amica-movement-0012: unknown parameter colour (parameters: timeout, events)",
                assertThrows(IllegalArgumentException.class,
                        () -> ops.setParameter("amica-movement", "colour", "red")).getMessage());
    }

    @Test
    void setOnAnActuatorSaysTheChangeIsPendingNotTheOldValue() {
        FakeDevice light = new FakeDevice("amica-light-0014", "AmicaSimpleLight", home.movement.uid, "Light 0014")
                .parameter(Parameter.writable("on", false, "the node's report"))
                .parameter(Parameter.readOnly("pending", null, "requested, not yet confirmed"))
                .parameter(Parameter.writable("label", "", "a writable parameter that is no command"));
        home.addDevice(home.movement, light, new NodeInfo(List.of("simple-light"), "0014", ""), "SimpleLightProvider");
        assertEquals("amica-light-0014: on=true requested, pending until the node confirms it (it reports on=false;"
                + " tinysep:events --device amica-light-0014 shows the answer)",
                ops.setParameter("amica-light", "on", "true"));
        assertEquals("amica-light-0014: label=Hall", ops.setParameter("amica-light", "label", "Hall"),
                "another parameter of a device with a pending request is not pending");
    }

    @Test
    void devicesFilterByUidPrefixNodeAddressDriverOrNameAndSayWhenNothingMatches() {
        assertEquals(List.of("amica-movement-0012", "amica-node-0012"),
                ops.devices("0012").stream().map(DeviceView::uid).sorted().toList(), "node address");
        assertEquals(List.of("flat-occupancy-1"), ops.devices("flat").stream().map(DeviceView::uid).toList());
        assertEquals(List.of("amica-node-0012", "amica-node-0013"),
                ops.devices("BusRadioAmica").stream().map(DeviceView::uid).sorted().toList(), "driver");
        assertEquals(4, ops.devices("").size());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> ops.devices("nosuch")).getMessage()
                .startsWith("no device matches 'nosuch' ("));
    }

    @Test
    void invokeRunsTheFunctionOrListsTheAvailableOnes() {
        assertEquals("amica-movement-0012 reset: did reset", ops.invoke("amica-movement-0012", "reset"));
        assertEquals(List.of("reset"), home.amicaMovement.invoked);
        assertEquals("cannot invoke reboot on amica-movement-0012: no function reboot (functions: reset)",
                assertThrows(IllegalArgumentException.class, () -> ops.invoke("amica-mov", "reboot")).getMessage());
        assertEquals("cannot invoke reset on flat-occupancy-1: no function reset (it has no functions)",
                assertThrows(IllegalArgumentException.class, () -> ops.invoke("flat-occ", "reset")).getMessage());
    }

    @Test
    void aDeviceThatThrowsUnexpectedlyGivesAOneLineError() {
        home.amicaMovement.failure = new NullPointerException("port is null");
        assertEquals("device amica-movement-0012 failed to run reset: NullPointerException: port is null",
                assertThrows(IllegalStateException.class, () -> ops.invoke("amica-movement-0012", "reset"))
                        .getMessage());
    }
}

package org.tinysep.runtime.internal.directory;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;

class DirectoryTest {

    @Test
    void providerInterfacesAreSimpleNamesWithoutDevice() {
        ProviderRecord r = ProviderRecord.of(1, "d", new String[] {"org.tinysep.api.sensor.MovementWithCoordinatesProvider",
            "org.tinysep.api.sensor.MovementProvider", "org.tinysep.api.device.Device"});
        assertEquals(List.of("MovementWithCoordinatesProvider", "MovementProvider"), r.interfaces());
    }

    @Test
    void interfacesAreGroupedByDeviceUidAndFollowRemoval() {
        DeviceDirectory dir = new DeviceDirectory();
        dir.put(ProviderRecord.of(1, "a", new String[] {"x.TemperatureProvider"}));
        dir.put(ProviderRecord.of(2, "a", new String[] {"x.LightBrightnessProvider", "x.TemperatureProvider"}));
        dir.put(ProviderRecord.of(3, "b", new String[] {"x.DoorProvider"}));
        assertEquals(List.of("LightBrightnessProvider", "TemperatureProvider"), dir.interfacesOf("a"));
        dir.removeProvider(2);
        assertEquals(List.of("TemperatureProvider"), dir.interfacesOf("a"));
        assertTrue(dir.interfacesOf("c").isEmpty());
    }

    @Test
    void aNewDevicesInterfacesAreFoundWithoutReadingEveryOtherDevice() {
        // issue 14: interfacesOf scanned every provider service for each new device (quadratic creation)
        DeviceDirectory dir = new DeviceDirectory();
        int devices = 2_000;
        for (int i = 0; i < devices; i++) {
            dir.put(ProviderRecord.of(i, "dev-" + i, new String[] {"x.MovementProvider"}));
            assertEquals(List.of("MovementProvider"), dir.interfacesOf("dev-" + i)); // as DeviceTracking asks
        }
        assertEquals(devices, dir.providersRead(), "provider records read: one per new device, not all of them");
        dir.put(ProviderRecord.of(7, "moved", new String[] {"x.DoorProvider"})); // a modified service, other uid
        assertTrue(dir.interfacesOf("dev-7").isEmpty());
        assertEquals(List.of("DoorProvider"), dir.interfacesOf("moved"));
    }

    @Test
    void nodeInfoReadsStringArraysCollectionsAndSingleValues() {
        Map<String, Object> props = new HashMap<>();
        props.put(DeviceProperties.NODE_TYPE, new String[] {"movement", "pet-collar"});
        props.put(DeviceProperties.NODE_ADDRESS, "0012");
        assertEquals(new NodeInfo(List.of("movement", "pet-collar"), "0012", ""), NodeInfo.from(props::get));
        props.put(DeviceProperties.NODE_TYPE, Set.of("door"));
        props.put(DeviceProperties.ROOM, "kitchen");
        assertEquals(new NodeInfo(List.of("door"), "0012", "kitchen"), NodeInfo.from(props::get));
        props.put(DeviceProperties.NODE_TYPE, "window");
        assertEquals(List.of("window"), NodeInfo.from(props::get).types());
        assertTrue(NodeInfo.from(k -> null).isEmpty());
    }

    @Test
    void driversSortByNameAndDevicesByUid() {
        Home home = new Home();
        assertEquals(List.of("AmicaMovement", "BusRadioAmica", "FlatOccupancy"),
                home.directory.drivers().stream().map(DriverRecord::name).toList());
        assertEquals(List.of("amica-movement-0012", "amica-node-0012", "amica-node-0013", "flat-occupancy-1"),
                home.directory.devices().stream().map(DeviceRecord::uid).toList());
    }

    @Test
    void announcementsCarryTheUidAsOriginAndTheDetails() {
        RecordingEventLog log = new RecordingEventLog();
        Announcer a = new Announcer(log);
        Home home = new Home();
        DriverRecord driver = home.directory.drivers().get(0);
        DeviceRecord device = home.directory.devices().get(0);
        a.driverAdded(driver);
        a.deviceCreated(device, home.directory.interfacesOf(device.uid()));
        a.deviceRemoved(device);
        a.driverRemoved(driver);
        List<EventEntry> e = log.entries;
        assertEquals(List.of(EventKind.DRIVER_ADDED, EventKind.DEVICE_CREATED, EventKind.DEVICE_REMOVED,
                EventKind.DRIVER_REMOVED), e.stream().map(EventEntry::kind).toList());
        assertEquals(List.of("amica-movement", "amica-movement-0012", "amica-movement-0012", "amica-movement"),
                e.stream().map(EventEntry::origin).toList());
        assertEquals("driver AmicaMovement added (bundle 8 org.tinysep.amica.movement)", e.get(0).message());
        assertEquals("AmicaMovement \"Movement 0012\" created; node types: movement; provides: MovementProvider, "
                + "MovementWithCoordinatesProvider", e.get(1).message());
        assertEquals("AmicaMovement \"Movement 0012\" removed", e.get(2).message());
        assertEquals("driver AmicaMovement removed", e.get(3).message());
    }
}

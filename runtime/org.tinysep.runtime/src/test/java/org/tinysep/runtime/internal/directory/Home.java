package org.tinysep.runtime.internal.directory;

import java.util.List;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.DeviceFunction;
import org.tinysep.api.device.Parameter;

/**
 * The thesis's Figure 3.3 scenario as fakes in a directory: a bus radio driver with two bus devices, AmicaMovement
 * with one device, FlatOccupancy with one device connected to the movement and the door.
 */
public final class Home {

    public final DeviceDirectory directory = new DeviceDirectory();
    public final FakeDriver bus = new FakeDriver("busradio-amica", "BusRadioAmica");
    public final FakeDriver movement = new FakeDriver("amica-movement", "AmicaMovement");
    public final FakeDriver flat = new FakeDriver("flat-occupancy", "FlatOccupancy");
    public final FakeDevice busMovement = new FakeDevice("amica-node-0012", "BusRadioAmica", bus.uid, "AmICA node 0012");
    public final FakeDevice busDoor = new FakeDevice("amica-node-0013", "BusRadioAmica", bus.uid, "AmICA node 0013");
    public final FakeDevice amicaMovement = new FakeDevice("amica-movement-0012", "AmicaMovement", movement.uid,
            "Movement 0012");
    public final FakeDevice flatOccupancy = new FakeDevice("flat-occupancy-1", "FlatOccupancy", flat.uid, "Flat");
    private long nextServiceId = 100;

    public Home() {
        bus.parameters.add(Parameter.readOnly("port", 47001, "UDP port"));
        bus.parameters.add(Parameter.readOnly("rejected", 2, "rejected packets"));
        addDriver(bus, 7, "org.tinysep.amica.busradio.udp");
        addDriver(movement, 8, "org.tinysep.amica.movement");
        addDriver(flat, 9, "org.tinysep.flatoccupancy");
        busMovement.parameter(Parameter.readOnly("rssi", -61, "signal"));
        addDevice(bus, busMovement, new NodeInfo(List.of("movement"), "0012", "kitchen"), "BusRadioAmicaProvider");
        addDevice(bus, busDoor, new NodeInfo(List.of("door"), "0013", ""), "BusRadioAmicaProvider");
        amicaMovement.connections.add(new ConnectionInfo("BusRadioAmicaProvider", busMovement.uid, true));
        amicaMovement.parameter(Parameter.writable("timeout", 30, "seconds without movement"));
        amicaMovement.parameter(Parameter.readOnly("events", 4, "movements seen"));
        amicaMovement.functions.add(new DeviceFunction("reset", "clears the counters"));
        addDevice(movement, amicaMovement, new NodeInfo(List.of("movement"), "0012", "kitchen"), "MovementProvider",
                "MovementWithCoordinatesProvider");
        flatOccupancy.connections.add(new ConnectionInfo("MovementProvider", amicaMovement.uid, false));
        flatOccupancy.connections.add(new ConnectionInfo("DoorProvider", "amica-door-0013", false));
        addDevice(flat, flatOccupancy, NodeInfo.NONE, "FlatOccupancyProvider");
    }

    public void addDriver(FakeDriver d, long bundleId, String bundleName) {
        directory.put(new DriverRecord(nextServiceId++, d.uid, d.name, bundleId, bundleName, d));
    }

    public void addDevice(FakeDriver owner, FakeDevice d, NodeInfo node, String... interfaces) {
        owner.devices.add(d);
        long id = nextServiceId++;
        String[] objectClass = new String[interfaces.length + 1];
        for (int i = 0; i < interfaces.length; i++) {
            objectClass[i] = "org.tinysep.api.x." + interfaces[i];
        }
        objectClass[interfaces.length] = "org.tinysep.api.device.Device";
        directory.put(ProviderRecord.of(id, d.uid, objectClass));
        directory.put(new DeviceRecord(id, d.uid, d.type, d.name, d.driverUid, node, d));
    }
}

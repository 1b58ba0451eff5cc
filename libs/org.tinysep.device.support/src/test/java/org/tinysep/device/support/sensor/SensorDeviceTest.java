package org.tinysep.device.support.sensor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.FakeAmicaBus;
import org.tinysep.device.support.testing.FakeSunSpotBus;
import org.tinysep.device.support.time.PlatformClock;

/** The shared behaviour of sensor devices, on a door declared in a few lines over a made-up payload format. */
class SensorDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-25T10:00:00Z");

    /** Payload [1] = open, [0] = closed, [7] = another type (a keep-alive), empty = malformed. */
    private static Object decode(byte[] payload) throws Exception {
        if (payload.length == 0) {
            throw new Exception("empty payload");
        }
        return payload[0] == 7 ? Integer.valueOf(7) : Boolean.valueOf(payload[0] == 1);
    }

    private static final class Door extends ContactSensorDevice<DoorListener> implements DoorProvider {
        Door(DriverContext context, Source<OpenState> source) {
            super(context, source, "door", "Door", "door", DoorProvider.class, DoorListener::doorChanged);
        }

        @Override
        public DoorKind kind() {
            return DoorKind.OUTER;
        }
    }

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final DriverContext context = new DriverContext(null, "d", "TestDoor", logs.reporter(),
            new PlatformClock(() -> T0));
    private final FakeAmicaBus bus = new FakeAmicaBus("1.20", "door", "movement");
    private final Door door = new Door(context,
            Source.amica(bus, SensorDeviceTest::decode, Boolean.class, (open, at) -> ContactSensorDevice.open(open)));

    private final List<String> heard = new ArrayList<>();

    private void listen() {
        door.connect(new DoorListener() {
            @Override
            public void doorChanged(DoorProvider source, OpenState state, boolean first, Instant at) {
                heard.add((first ? "first " : "change ") + state + "@" + (at.getEpochSecond() - T0.getEpochSecond()));
            }

            @Override
            public void doorChanged(DoorProvider source, OpenState state, Instant at) {
                heard.add("1.0 " + state); // not called: the device calls the 1.1 method
            }
        });
    }

    @Test
    void theFirstReportEstablishesTheStateRepeatsAndOtherPayloadsAreNotChanges() {
        listen();
        assertEquals(OpenState.UNKNOWN, door.state());
        assertEquals("UNKNOWN", parameter("state"));

        door.payloadReceived(bus, new byte[] {7}, T0); // not ours
        door.payloadReceived(bus, new byte[0], T0); // malformed: the bus radio counted it
        assertEquals(DeviceStatus.State.UNKNOWN, door.status().state(), "nothing of ours arrived yet");
        door.payloadReceived(bus, new byte[] {0}, T0.plusSeconds(1));
        door.payloadReceived(bus, new byte[] {0}, T0.plusSeconds(2));
        door.payloadReceived(bus, new byte[] {1}, T0.plusSeconds(3));
        door.payloadReceived(bus, new byte[] {0}, T0.plusSeconds(4));

        assertEquals(List.of("first CLOSED@1", "change OPEN@3", "change CLOSED@4"), heard);
        assertEquals(DeviceStatus.State.ONLINE, door.status().state());
        assertEquals("CLOSED", parameter("state"));
        assertEquals(T0.plusSeconds(4).toString(), parameter("since"));
        assertEquals(List.of("door closed", "door opened", "door closed"), logs.events().stream()
                .filter(e -> e.kind() == EventKind.DEVICE_EVENT).map(e -> e.message()).toList());
    }

    @Test
    void aListenerOfSensorApi10HearsEveryCallAsBefore() {
        door.connect((source, state, at) -> heard.add(state.name()));
        door.payloadReceived(bus, new byte[] {0}, T0);
        door.payloadReceived(bus, new byte[] {1}, T0.plusSeconds(1));
        assertEquals(List.of("CLOSED", "OPEN"), heard);
    }

    @Test
    void aSunSpotSourceTakesItsSensorTypeAndRejectsWhatItCannotRead() {
        FakeSunSpotBus sunSpot = new FakeSunSpotBus();
        Door d = new Door(context, Source.sunSpot(sunSpot, new Source.Frames(3, "door"), SensorDeviceTest::decode,
                Boolean.class, (open, at) -> ContactSensorDevice.open(open)));
        d.payloadReceived(sunSpot, 4, new byte[] {1}, T0); // another sensor of the node
        assertEquals(DeviceStatus.State.UNKNOWN, d.status().state());
        d.payloadReceived(sunSpot, 3, new byte[] {7}, T0);
        d.payloadReceived(sunSpot, 3, new byte[0], T0);
        assertEquals(DeviceStatus.State.ERROR, d.status().state());
        assertEquals("rejected payload: empty payload", d.status().detail());
        assertEquals("2", d.parameters().stream().filter(p -> p.key().equals("rejectedPayloads"))
                .map(Parameter::value).findFirst().orElseThrow());
        d.payloadReceived(sunSpot, 3, new byte[] {1}, T0.plusSeconds(1));
        assertEquals(DeviceStatus.State.ONLINE, d.status().state(), "a good payload clears the error");
        assertEquals(OpenState.OPEN, d.state());
        d.payloadReceived(bus, new byte[] {0}, T0.plusSeconds(2)); // not its family
        assertEquals(OpenState.OPEN, d.state());
    }

    @Test
    void theListenerCallIsToldTheDeviceAsItsProviderInterface() {
        List<DoorProvider> sources = new ArrayList<>();
        door.connect((source, state, at) -> sources.add(source));
        door.payloadReceived(bus, new byte[] {1}, T0);
        assertEquals(List.of(door), sources);
    }

    @Test
    void aSensorWithoutListenerCallMustOverrideTell() {
        SensorDevice<DoorListener, OpenState> bare = new SensorDevice<>(context, Source.amica(bus,
                SensorDeviceTest::decode, Boolean.class, (open, at) -> ContactSensorDevice.open(open)), "door", "Bare") {
        };
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> bare.tell((source, state, at) -> { }, OpenState.OPEN, true, T0));
        assertTrue(e.getMessage().contains("gives no listener call and does not override tell"), e.getMessage());
    }

    private String parameter(String key) {
        return door.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }
}

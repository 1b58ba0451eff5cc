package org.tinysep.amica.door.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.PlatformClock;
import org.tinysep.device.support.RecordingLogs;

/** Reed-switch payloads in, door changes out; repeated states are not re-announced. */
class AmicaDoorDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    private final BusRadioAmicaProvider bus = new BusRadioAmicaProvider() {
        @Override
        public String deviceUid() {
            return "bus-1";
        }

        @Override
        public Connection connect(BusRadioAmicaListener listener) {
            throw new UnsupportedOperationException("not needed here");
        }

        @Override
        public String nodeId() {
            return "1.20";
        }

        @Override
        public Set<String> nodeTypes() {
            return Set.of("door");
        }

        @Override
        public void send(byte[] payload) {
            throw new UnsupportedOperationException("a door sends nothing");
        }
    };

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final AmicaDoorDevice door = new AmicaDoorDevice(
            new DriverContext(null, "d", "AmicaDoor", logs.reporter(), new PlatformClock(() -> T0)), bus);

    @Test
    void announcesOnlyChanges() {
        List<String> seen = new ArrayList<>();
        door.connect((src, state, at) -> seen.add(state + "@" + at.getEpochSecond()));

        door.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(false)), T0);
        door.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(false)), T0.plusSeconds(1));
        door.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(true)), T0.plusSeconds(2));
        door.payloadReceived(bus, AmicaPayloads.encode(new KeepAlive(1, 2, 3, 2, 5)), T0.plusSeconds(3));
        door.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(true)), T0.plusSeconds(3));

        long t = T0.getEpochSecond();
        assertEquals(List.of("CLOSED@" + t, "OPEN@" + (t + 2)), seen);
        assertEquals(OpenState.OPEN, door.state());
    }

    @Test
    void kindIsConfigurableAndValidated() {
        assertEquals(DoorKind.OUTER, door.kind());
        door.setParameter("kind", "inner");
        assertEquals(DoorKind.INNER, door.kind());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> door.setParameter("kind", "sideways"));
        assertEquals("kind must be OUTER or INNER, was 'sideways'", e.getMessage());
        assertEquals(DoorKind.INNER, door.kind(), "unchanged after a bad value");
        assertThrows(IllegalArgumentException.class, () -> door.setParameter("state", "OPEN"));
    }
}

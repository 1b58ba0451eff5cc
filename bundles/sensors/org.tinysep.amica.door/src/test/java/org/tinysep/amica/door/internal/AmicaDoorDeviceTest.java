package org.tinysep.amica.door.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.tinysep.device.support.testing.TestPlatform.T0;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.device.support.testing.FakeAmicaBus;
import org.tinysep.device.support.testing.TestPlatform;

/** Reed-switch payloads in, door changes out; repeated states are not re-announced. */
class AmicaDoorDeviceTest {

    private final FakeAmicaBus bus = new FakeAmicaBus("1.20", "door");

    private final TestPlatform platform = new TestPlatform();
    private final AmicaDoorDevice door = new AmicaDoorDevice(platform.context("AmicaDoor"), bus);

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

    /** Issue 16: the first report establishes the state and says so; every later call is a change. */
    @Test
    void theFirstReportEstablishesTheStateAndListenersAreToldSo() {
        List<String> seen = new ArrayList<>();
        door.connect(new DoorListener() {
            @Override
            public void doorChanged(DoorProvider source, OpenState state, Instant at) {
                seen.add("old " + state);
            }

            @Override
            public void doorChanged(DoorProvider source, OpenState state, boolean first, Instant at) {
                seen.add((first ? "first " : "change ") + state);
            }
        });
        List<String> old = new ArrayList<>();
        door.connect((src, state, at) -> old.add(state.name())); // a 1.0 listener hears every call as before

        door.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(false)), T0);
        door.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(false)), T0.plusSeconds(1));
        door.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(true)), T0.plusSeconds(2));
        door.payloadReceived(bus, AmicaPayloads.encode(new ReedSwitchStatus(false)), T0.plusSeconds(3));

        assertEquals(List.of("first CLOSED", "change OPEN", "change CLOSED"), seen);
        assertEquals(List.of("CLOSED", "OPEN", "CLOSED"), old);
        assertEquals(0, bus.sent.size(), "a door is never sent anything");
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

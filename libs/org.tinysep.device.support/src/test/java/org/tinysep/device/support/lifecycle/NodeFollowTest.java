package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Provider;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/** A device follows its bus node (issue 32, item 3): OFFLINE with the reason while the node is, no entry of its own. */
class NodeFollowTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    interface Input {
    }

    /** A bus device as the bus radios make it: a device that provides the bus interface and its node's health. */
    private static final class BusNode extends AbstractDevice implements Provider<Input>, NodeHealthSource {
        Instant silentSince;

        BusNode(DriverContext c) {
            super(c, "bus-1.4", "BusRadioA", "AmICA node 1.4");
        }

        void set(DeviceStatus.State state, String detail) {
            status(state, detail);
        }

        @Override
        public String deviceUid() {
            return uid();
        }

        @Override
        public Connection connect(Input listener) {
            return new ConsumptionsTest.Handle();
        }

        @Override
        public NodeHealth health() {
            return new NodeHealth(uid(), "1.4", Set.of("simpleLight"), status().state() == DeviceStatus.State.ONLINE,
                    silentSince, silentSince, Duration.ofMinutes(1), null, false, 0, 0, 0);
        }
    }

    private static final class Light extends AbstractDevice {
        Light(DriverContext c) {
            super(c, "light-1", "SimpleLight", "Hall light");
        }

        void online() {
            status(DeviceStatus.State.ONLINE, "");
        }

        <L> void use(Provider<L> p, L listener) {
            connect(p, Provider.class, listener, true);
        }
    }

    /** A device that provides something but is no bus device (no node health). */
    private static final class Sensor extends AbstractDevice implements Provider<Input> {
        Sensor(DriverContext c) {
            super(c, "sensor-1", "Door", "Door");
        }

        @Override
        public String deviceUid() {
            return uid();
        }

        @Override
        public Connection connect(Input listener) {
            return new ConsumptionsTest.Handle();
        }
    }

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final DriverContext context = new DriverContext(null, "drv", "Test", logs.reporter(),
            new PlatformClock(() -> T0));
    private final BusNode bus = new BusNode(context);
    private final Light light = new Light(context);

    private long statusEntries(String uid) {
        return logs.events().stream().filter(e -> e.kind() == EventKind.STATUS && e.origin().equals(uid)).count();
    }

    @Test
    void aDeviceIsOfflineWhileItsBusNodeIsSilentAndOnlineWhenItIsHeardAgain() {
        bus.set(DeviceStatus.State.ONLINE, "");
        light.use(bus, new Input() { });
        light.online();
        assertEquals(DeviceStatus.State.ONLINE, light.status().state());
        long before = statusEntries(light.uid());

        bus.silentSince = T0.minusSeconds(300);
        bus.set(DeviceStatus.State.OFFLINE, "silent since 2026-11-22 09:55:00 UTC");
        DeviceStatus s = light.status();
        assertEquals(DeviceStatus.State.OFFLINE, s.state());
        assertTrue(s.detail().startsWith("its radio node 1.4 has been silent since 2026-11-22 09:55:00 UTC"),
                s.detail());
        assertTrue(s.detail().contains("bus-1.4"), s.detail());
        assertEquals(before, statusEntries(light.uid()), "the bus device's entry tells it; the light writes none");

        bus.silentSince = null;
        bus.set(DeviceStatus.State.ONLINE, "");
        assertEquals(DeviceStatus.State.ONLINE, light.status().state());
    }

    @Test
    void aBusNodeOfflineForAnotherReasonIsNamedWithItsDetail() {
        light.use(bus, new Input() { });
        light.online();
        bus.set(DeviceStatus.State.OFFLINE, "its link /dev/ttyUSB0 went down");
        assertEquals("its radio node 1.4 is OFFLINE: its link /dev/ttyUSB0 went down; this device is OFFLINE with "
                + "it until the node is heard again (bus device bus-1.4)", light.status().detail());
    }

    @Test
    void aProviderThatIsNoBusNodeIsNotFollowedAndAGoneNodeIsForgotten() {
        Sensor other = new Sensor(context);
        other.status(DeviceStatus.State.ONLINE, "");
        light.use(other, new Input() { }); // a device, but no node health: e.g. a sensor a service listens to
        light.online();
        other.status(DeviceStatus.State.OFFLINE, "silent");
        assertEquals(DeviceStatus.State.ONLINE, light.status().state(), "only bus devices are followed");

        light.use(bus, new Input() { });
        bus.set(DeviceStatus.State.OFFLINE, "link down");
        assertEquals(DeviceStatus.State.OFFLINE, light.status().state());
        light.providerGone(bus.uid());
        assertEquals(DeviceStatus.State.ONLINE, light.status().state(), "a removed bus device is not followed");
    }
}

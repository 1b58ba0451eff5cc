package org.tinysep.amica.actuator.base;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.amica.actuator.base.testing.FakeBus;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * The shared actuator logic, through a device built on Heater Control: status in, value out; a request sends the
 * payload and waits for the node. The actuator bundles' own tests check only their wiring.
 */
class PercentActuatorDeviceTest {

    /** A heater-like device, as an actuator bundle writes one. */
    static final class Heater extends PercentActuatorDevice<HeaterControl, PotencyListener> {
        Heater(DriverContext context, FakeBus bus) {
            super(context, bus, "Heater", NodeType.HEATER, "potency", HeaterControl.class, HeaterControl::percent,
                    HeaterControl::new, Heater.class, (listener, self, value, at) -> listener.changed(value, at));
        }
    }

    interface PotencyListener {
        void changed(Percent value, Instant at);
    }


    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    private final FakeBus bus = new FakeBus("1.21", "heater");
    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final Heater device = new Heater(new DriverContext(null, "d", "TestHeater", logs.reporter(),
            new PlatformClock(() -> T0)), bus);
    private final List<String> heard = new ArrayList<>();

    PercentActuatorDeviceTest() {
        device.connect((potency, at) -> heard.add(potency + "@"
                + (at.getEpochSecond() - T0.getEpochSecond())));
    }

    private void receive(AmicaPayload payload, int second) {
        device.payloadReceived(bus, AmicaPayloads.encode(payload), T0.plusSeconds(second));
    }

    @Test
    void statusReportsBecomePotencyChangesAndOtherPayloadsAreIgnored() {
        assertEquals(Optional.empty(), device.level());
        receive(new HeaterControl(30), 0);
        receive(new HeaterControl(30), 10);
        receive(new LightControl(90), 11);
        receive(new ReedSwitchStatus(true), 11);
        receive(new KeepAlive(5, 3000, 1, 0x10, 9), 11);
        receive(new HeaterControl(75), 20);

        assertEquals(List.of("30%@0", "75%@20"), heard);
        assertEquals(Optional.of(Percent.of(75)), device.level());
        assertEquals(DeviceStatus.State.ONLINE, device.status().state());
        assertEquals(0, bus.sent.size());
        assertEquals("Heater 1.21", device.name());
    }

    @Test
    void setLevelSendsTheExactCommandAndWaitsForTheNodesNextStatus() {
        receive(new HeaterControl(0), 0);
        device.setLevel(Percent.of(40));

        assertEquals(1, bus.sent.size());
        assertArrayEquals(new byte[] {5, 8, 0, 40}, bus.sent.get(0));
        assertEquals(Optional.of(Percent.of(0)), device.level(), "unchanged before the node confirms");
        assertEquals("40%", parameter("pending"));
        assertEquals(List.of("0%@0"), heard);

        receive(new HeaterControl(40), 10);
        assertEquals(Optional.of(Percent.of(40)), device.level());
        assertEquals(List.of("0%@0", "40%@10"), heard);
        assertEquals("", parameter("pending"));
        assertEquals(List.of("potency 0%", "potency 40% requested", "potency 40% (confirmed)"),
                deviceEvents());
    }

    @Test
    void thePotencyParameterSetsAndRejectsBadValuesWithoutChangingAnything() {
        device.setParameter("potency", "65%");
        assertArrayEquals(new byte[] {5, 8, 0, 65}, bus.sent.get(0));
        for (String bad : new String[] {"101", "-5", "half", ""}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> device.setParameter("potency", bad));
            assertEquals("potency must be a whole percentage 0..100, was '" + bad + "'", e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> device.setLevel(null));
        assertEquals(1, bus.sent.size(), "nothing sent for bad values");
        assertEquals("65%", parameter("pending"));
    }

    @Test
    void aCommandTheNodeDoesNotTakeIsGivenUpByAReportTwoIntervalsLater() {
        receive(new HeaterControl(10), 0);
        device.setLevel(Percent.of(90)); // at T0
        receive(new HeaterControl(10), 0);
        receive(new HeaterControl(10), 10);
        receive(new HeaterControl(10), 19);
        assertEquals("90%", parameter("pending"), "reports within two intervals may predate the command");
        receive(new HeaterControl(10), 20);
        assertEquals("", parameter("pending"));
        assertTrue(deviceEvents().contains("potency 90% not confirmed: the node reported potency 10% at "
                + "2026-11-22T10:00:20Z, 20 s after the request (2026-11-22T10:00:00Z); request given up"),
                deviceEvents().toString());
    }

    @Test
    void aBusRadioThatCannotSendIsADeviceStatusNotAnException() {
        bus.failure = new IllegalStateException("bus radio is closed");
        device.setLevel(Percent.of(50));
        assertEquals(DeviceStatus.State.ERROR, device.status().state());
        assertEquals("", parameter("pending"));
    }

    private List<String> deviceEvents() {
        return logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT).map(e -> e.message()).toList();
    }

    private String parameter(String key) {
        return device.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }
}

package org.tinysep.amica.simplelight.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.device.support.testing.TestPlatform.T0;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.actuator.base.testing.FakeBus;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.testing.FakeAmicaBus;
import org.tinysep.device.support.testing.TestPlatform;

/** Light Control status in, on/off out; switching sends Light Control 100/0 and waits for the node to confirm. */
class AmicaSimpleLightDeviceTest {

    private final FakeBus bus = new FakeBus("1.30", "simple-light", "movement");
    private final TestPlatform platform = new TestPlatform();
    private final AmicaSimpleLightDevice light = new AmicaSimpleLightDevice(
            platform.context(AmicaSimpleLightDriver.NAME), bus);
    private final List<String> heard = new ArrayList<>();

    AmicaSimpleLightDeviceTest() {
        light.connect((source, on, at) -> heard.add((on ? "on@" : "off@") + (at.getEpochSecond() - T0.getEpochSecond())));
    }

    private void receive(AmicaPayload payload, int second) {
        light.payloadReceived(bus, AmicaPayloads.encode(payload), T0.plusSeconds(second));
    }

    @Test
    void statusReportsBecomeOnOffChangesAndOtherPayloadsAreIgnored() {
        assertEquals(Optional.empty(), light.isOn());
        receive(new LightControl(0), 0);
        receive(new LightControl(0), 10);
        receive(new MotionDetection(true), 11);
        receive(new HeaterControl(80), 11);
        receive(new KeepAlive(5, 3000, 1, 0x81, 9), 11);
        receive(new LightControl(1), 20);
        receive(new LightControl(100), 30);
        receive(new LightControl(0), 40);

        assertEquals(List.of("off@0", "on@20", "off@40"), heard);
        assertEquals(Optional.of(false), light.isOn());
        assertEquals(DeviceStatus.State.ONLINE, light.status().state());
        assertEquals(0, bus.sent.size());
    }

    @Test
    void switchingSendsTheExactCommandAndWaitsForTheNodesNextStatus() {
        receive(new LightControl(0), 0);
        light.switchLight(true);

        assertEquals(1, bus.sent.size());
        assertArrayEquals(new byte[] {5, 2, 0, 100}, bus.sent.get(0));
        assertEquals(Optional.of(false), light.isOn(), "not on before the node confirms");
        assertEquals(List.of("off@0"), heard);
        assertEquals("true", parameter("pending"));
        assertEquals("false", parameter("on"));

        receive(new LightControl(100), 10);
        assertEquals(Optional.of(true), light.isOn());
        assertEquals(List.of("off@0", "on@10"), heard);
        assertEquals("", parameter("pending"));

        light.switchLight(false);
        assertArrayEquals(new byte[] {5, 2, 0, 0}, bus.sent.get(1));
        assertEquals(List.of("off@0", "on@10"), heard);
        receive(new LightControl(0), 20);
        assertEquals(List.of("off@0", "on@10", "off@20"), heard);
        assertEquals(List.of("light off", "light on requested", "light on (confirmed)", "light off requested",
                "light off (confirmed)"), deviceEvents());
    }

    @Test
    void theOnParameterSwitchesLikeSwitchLightAndRejectsNonsense() {
        light.setParameter("on", "true");
        assertArrayEquals(new byte[] {5, 2, 0, 100}, bus.sent.get(0));
        light.setParameter("on", "off");
        assertArrayEquals(new byte[] {5, 2, 0, 0}, bus.sent.get(1));
        assertEquals("false", parameter("pending"));

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> light.setParameter("on", "maybe"));
        assertEquals("on must be true or false (or on/off), was 'maybe'", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> light.setParameter("pending", "true"));
        assertEquals(2, bus.sent.size(), "nothing sent for a bad value");
        assertEquals("false", parameter("pending"), "unchanged by a bad value");
    }

    @Test
    void staleReportsWithinTwoReportIntervalsAreNoContradiction() {
        receive(new LightControl(0), 0);
        light.switchLight(true); // at T0
        receive(new LightControl(0), 0); // sent before the command reached the node, delivered late
        receive(new LightControl(0), 10);
        receive(new LightControl(0), 19);
        assertEquals("true", parameter("pending"));
        receive(new LightControl(100), 19);
        assertEquals(List.of("off@0", "on@19"), heard);
        assertTrue(deviceEvents().stream().noneMatch(e -> e.contains("given up")), deviceEvents().toString());
    }

    @Test
    void aCommandTheNodeDoesNotTakeIsGivenUpByAReportTwoIntervalsLaterThatSaysWhichReport() {
        receive(new LightControl(0), 0);
        light.switchLight(true);
        receive(new LightControl(0), 10); // may have crossed the command
        assertEquals("true", parameter("pending"));
        receive(new LightControl(0), 20);
        assertEquals("", parameter("pending"));
        assertEquals(List.of("off@0"), heard);
        assertTrue(deviceEvents().contains("light on not confirmed: the node reported light off at "
                + "2026-11-22T10:00:20Z, 20 s after the request (2026-11-22T10:00:00Z); request given up"),
                deviceEvents().toString());
    }

    @Test
    void aBusRadioThatCannotSendIsADeviceStatusNotAnException() {
        bus.failure = new IllegalStateException("bus radio is closed");
        light.switchLight(true);
        assertEquals(DeviceStatus.State.ERROR, light.status().state());
        assertEquals("", parameter("pending"));
        assertTrue(deviceEvents().contains("light on not sent: bus radio is closed"), deviceEvents().toString());
        receive(new LightControl(0), 10);
        assertEquals(DeviceStatus.State.ONLINE, light.status().state(), "the node is heard again");
    }

    /** Issue 29: the command is on the wire before its "requested" line is written (the log's threads wake then). */
    @Test
    void theCommandIsSentBeforeItsRequestIsLogged() {
        List<Integer> entriesAtSend = new ArrayList<>();
        FakeAmicaBus wire = new FakeAmicaBus("1.31", "simple-light") {
            @Override
            public void send(byte[] payload) {
                entriesAtSend.add(platform.logs.events().size());
                super.send(payload);
            }
        };
        AmicaSimpleLightDevice other = new AmicaSimpleLightDevice(platform.context(AmicaSimpleLightDriver.NAME), wire);
        int before = platform.logs.events().size();
        other.switchLight(true);
        assertEquals(List.of(before), entriesAtSend, "event-log entries when the command was sent");
        assertEquals(before + 1, platform.logs.events().size());
        assertEquals("light on requested", platform.logs.events().get(before).message());
    }

    private List<String> deviceEvents() {
        return platform.logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT).map(e -> e.message()).toList();
    }

    private String parameter(String key) {
        return light.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }
}

package org.tinysep.amica.dimmablelight.internal;

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
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.amica.protocol.SpeakerControl;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.PlatformClock;
import org.tinysep.device.support.RecordingLogs;

/** Light Control status in, brightness out; setBrightness sends Light Control A and waits for the node. */
class AmicaDimmableLightDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    private final FakeBus bus = new FakeBus("1.20", "dimmable-light");
    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final AmicaDimmableLightDevice light = new AmicaDimmableLightDevice(new DriverContext(null, "d",
            AmicaDimmableLightDriver.NAME, logs.reporter(), new PlatformClock(() -> T0)), bus);
    private final List<String> heard = new ArrayList<>();

    AmicaDimmableLightDeviceTest() {
        light.connect((source, brightness, at) -> heard.add(brightness + "@"
                + (at.getEpochSecond() - T0.getEpochSecond())));
    }

    private void receive(AmicaPayload payload, int second) {
        light.payloadReceived(bus, AmicaPayloads.encode(payload), T0.plusSeconds(second));
    }

    @Test
    void statusReportsBecomeBrightnessChangesAndOtherPayloadsAreIgnored() {
        assertEquals(Optional.empty(), light.brightness());
        receive(new LightControl(30), 0);
        receive(new LightControl(30), 10);
        receive(new SpeakerControl(90), 11);
        receive(new ReedSwitchStatus(true), 11);
        receive(new KeepAlive(5, 3000, 1, 0x08, 9), 11);
        receive(new LightControl(75), 20);

        assertEquals(List.of("30%@0", "75%@20"), heard);
        assertEquals(Optional.of(Percent.of(75)), light.brightness());
        assertEquals(DeviceStatus.State.ONLINE, light.status().state());
        assertEquals(0, bus.sent.size());
    }

    @Test
    void setBrightnessSendsTheExactCommandAndWaitsForTheNodesNextStatus() {
        receive(new LightControl(0), 0);
        light.setBrightness(Percent.of(40));

        assertEquals(1, bus.sent.size());
        assertArrayEquals(new byte[] {5, 2, 0, 40}, bus.sent.get(0)); // thesis Table 3.1 example
        assertEquals(Optional.of(Percent.of(0)), light.brightness(), "unchanged before the node confirms");
        assertEquals("40%", parameter("pending"));
        assertEquals(List.of("0%@0"), heard);

        receive(new LightControl(40), 10);
        assertEquals(Optional.of(Percent.of(40)), light.brightness());
        assertEquals(List.of("0%@0", "40%@10"), heard);
        assertEquals("", parameter("pending"));
        assertEquals(List.of("brightness 0%", "brightness 40% requested", "brightness 40% (confirmed)"),
                deviceEvents());
    }

    @Test
    void theBrightnessParameterSetsAndRejectsBadValuesWithoutChangingAnything() {
        light.setParameter("brightness", "65%");
        assertArrayEquals(new byte[] {5, 2, 0, 65}, bus.sent.get(0));
        for (String bad : new String[] {"101", "-5", "half", ""}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> light.setParameter("brightness", bad));
            assertEquals("brightness must be a whole percentage 0..100, was '" + bad + "'", e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> light.setBrightness(null));
        assertEquals(1, bus.sent.size(), "nothing sent for bad values");
        assertEquals("65%", parameter("pending"));
    }

    @Test
    void aCommandTheNodeDoesNotTakeIsGivenUpAfterTwoStatusReports() {
        receive(new LightControl(10), 0);
        light.setBrightness(Percent.of(90));
        receive(new LightControl(10), 10);
        assertEquals("90%", parameter("pending"));
        receive(new LightControl(10), 20);
        assertEquals("", parameter("pending"));
        assertTrue(deviceEvents().contains("brightness 90% not confirmed: the node still reports brightness 10% "
                + "after 2 status report(s); request given up"), deviceEvents().toString());
    }

    @Test
    void aBusRadioThatCannotSendIsADeviceStatusNotAnException() {
        bus.failure = new IllegalStateException("bus radio is closed");
        light.setBrightness(Percent.of(50));
        assertEquals(DeviceStatus.State.ERROR, light.status().state());
        assertEquals("", parameter("pending"));
    }

    private List<String> deviceEvents() {
        return logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT).map(e -> e.message()).toList();
    }

    private String parameter(String key) {
        return light.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }
}

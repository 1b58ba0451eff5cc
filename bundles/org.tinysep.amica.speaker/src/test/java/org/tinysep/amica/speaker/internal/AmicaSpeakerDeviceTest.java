package org.tinysep.amica.speaker.internal;

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

/** Speaker Control status in, volume out; setVolume sends Speaker Control A and waits for the node. */
class AmicaSpeakerDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    private final FakeBus bus = new FakeBus("1.22", "speaker");
    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final AmicaSpeakerDevice device = new AmicaSpeakerDevice(new DriverContext(null, "d",
            AmicaSpeakerDriver.NAME, logs.reporter(), new PlatformClock(() -> T0)), bus);
    private final List<String> heard = new ArrayList<>();

    AmicaSpeakerDeviceTest() {
        device.connect((source, volume, at) -> heard.add(volume + "@"
                + (at.getEpochSecond() - T0.getEpochSecond())));
    }

    private void receive(AmicaPayload payload, int second) {
        device.payloadReceived(bus, AmicaPayloads.encode(payload), T0.plusSeconds(second));
    }

    @Test
    void statusReportsBecomeVolumeChangesAndOtherPayloadsAreIgnored() {
        assertEquals(Optional.empty(), device.volume());
        receive(new SpeakerControl(30), 0);
        receive(new SpeakerControl(30), 10);
        receive(new LightControl(90), 11);
        receive(new ReedSwitchStatus(true), 11);
        receive(new KeepAlive(5, 3000, 1, 0x20, 9), 11);
        receive(new SpeakerControl(75), 20);

        assertEquals(List.of("30%@0", "75%@20"), heard);
        assertEquals(Optional.of(Percent.of(75)), device.volume());
        assertEquals(DeviceStatus.State.ONLINE, device.status().state());
        assertEquals(0, bus.sent.size());
    }

    @Test
    void setVolumeSendsTheExactCommandAndWaitsForTheNodesNextStatus() {
        receive(new SpeakerControl(0), 0);
        device.setVolume(Percent.of(40));

        assertEquals(1, bus.sent.size());
        assertArrayEquals(new byte[] {5, 4, 0, 40}, bus.sent.get(0));
        assertEquals(Optional.of(Percent.of(0)), device.volume(), "unchanged before the node confirms");
        assertEquals("40%", parameter("pending"));
        assertEquals(List.of("0%@0"), heard);

        receive(new SpeakerControl(40), 10);
        assertEquals(Optional.of(Percent.of(40)), device.volume());
        assertEquals(List.of("0%@0", "40%@10"), heard);
        assertEquals("", parameter("pending"));
        assertEquals(List.of("volume 0%", "volume 40% requested", "volume 40% (confirmed)"),
                deviceEvents());
    }

    @Test
    void theVolumeParameterSetsAndRejectsBadValuesWithoutChangingAnything() {
        device.setParameter("volume", "65%");
        assertArrayEquals(new byte[] {5, 4, 0, 65}, bus.sent.get(0));
        for (String bad : new String[] {"101", "-5", "half", ""}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> device.setParameter("volume", bad));
            assertEquals("volume must be a whole percentage 0..100, was '" + bad + "'", e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> device.setVolume(null));
        assertEquals(1, bus.sent.size(), "nothing sent for bad values");
        assertEquals("65%", parameter("pending"));
    }

    @Test
    void aCommandTheNodeDoesNotTakeIsGivenUpAfterTwoStatusReports() {
        receive(new SpeakerControl(10), 0);
        device.setVolume(Percent.of(90));
        receive(new SpeakerControl(10), 10);
        assertEquals("90%", parameter("pending"));
        receive(new SpeakerControl(10), 20);
        assertEquals("", parameter("pending"));
        assertTrue(deviceEvents().contains("volume 90% not confirmed: the node still reports volume 10% "
                + "after 2 status report(s); request given up"), deviceEvents().toString());
    }

    @Test
    void aBusRadioThatCannotSendIsADeviceStatusNotAnException() {
        bus.failure = new IllegalStateException("bus radio is closed");
        device.setVolume(Percent.of(50));
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

package org.tinysep.sunspot.light.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.PlatformClock;
import org.tinysep.device.support.RecordingLogs;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** Light Status payloads in, brightness changes out. */
class SunSpotLightDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    private static final int LIGHT = SunSpotSensorType.LIGHT.code();

    private final FakeSunSpotBus bus = new FakeSunSpotBus();
    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final SunSpotLightDevice sensor = new SunSpotLightDevice(
            new DriverContext(null, "d", "SunSpotLight", logs.reporter(), new PlatformClock(() -> T0)), bus);
    private final List<String> heard = new ArrayList<>();

    SunSpotLightDeviceTest() {
        sensor.connect((src, b, at) -> heard.add(b + "@" + (at.getEpochSecond() - T0.getEpochSecond())));
    }

    private void feed(int percent, int second) {
        sensor.payloadReceived(bus, LIGHT, SunSpotPayloads.encode(new LightStatus(percent)), T0.plusSeconds(second));
    }

    @Test
    void listenersHearChangesOnly() {
        assertEquals(Optional.empty(), sensor.brightness());
        feed(40, 0);
        feed(40, 10);
        feed(0, 20);
        feed(100, 30);
        feed(100, 40);

        assertEquals(List.of("40%@0", "0%@20", "100%@30"), heard);
        assertEquals(Optional.of(Percent.FULL), sensor.brightness());
        assertEquals(T0.plusSeconds(40).toString(), parameter("lastUpdate"));
        assertEquals(DeviceStatus.State.ONLINE, sensor.status().state());
    }

    @Test
    void otherSensorsOfTheNodeAreIgnoredAndBadPayloadsGiveNoEventAndNoException() {
        sensor.payloadReceived(bus, SunSpotSensorType.TEMPERATURE.code(),
                SunSpotPayloads.encode(new TemperatureStatus(21.0)), T0);
        sensor.payloadReceived(bus, SunSpotSensorType.MOVEMENT.code(),
                SunSpotPayloads.encode(new MovementDetection(true)), T0);
        assertEquals(DeviceStatus.State.UNKNOWN, sensor.status().state(), "nothing of ours arrived yet");

        sensor.payloadReceived(bus, LIGHT, new byte[] {4, 1, 0, (byte) 150}, T0); // 150 %
        sensor.payloadReceived(bus, LIGHT, new byte[] {4, 1, 0, (byte) 0xFF}, T0); // 255 %, or -1 if signed
        sensor.payloadReceived(bus, LIGHT, new byte[] {4, 1, 0}, T0);
        sensor.payloadReceived(bus, LIGHT, SunSpotPayloads.encode(new TemperatureStatus(21.0)), T0);

        assertEquals(List.of(), heard);
        assertTrue(sensor.brightness().isEmpty());
        assertEquals("4", parameter("rejectedPayloads"));
        assertEquals(DeviceStatus.State.ERROR, sensor.status().state());

        feed(55, 1);
        assertEquals(List.of("55%@1"), heard);
        assertEquals(DeviceStatus.State.ONLINE, sensor.status().state());
    }

    @Test
    void aSensorHasNothingToSetOrInvoke() {
        assertThrows(IllegalArgumentException.class, () -> sensor.setParameter("brightness", "50"));
        assertEquals(List.of(), sensor.functions());
        assertEquals(List.of("name", "room"), sensor.parameters().stream().filter(Parameter::writable)
                .map(Parameter::key).toList(), "only the common name and room");
    }

    private String parameter(String key) {
        return sensor.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }
}

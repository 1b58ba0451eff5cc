package org.tinysep.sunspot.light.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.device.support.testing.SunSpotDeviceTestSupport;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.Percent;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** Light Status payloads in, brightness changes out. */
class SunSpotLightDeviceTest extends SunSpotDeviceTestSupport<SunSpotLightDevice, Integer> {

    SunSpotLightDeviceTest() {
        super("SunSpotLight", SunSpotSensorType.LIGHT.code(), SunSpotLightDevice::new,
                percent -> SunSpotPayloads.encode(new LightStatus(percent)));
        sensor.connect((src, b, at) -> hear(b, at));
    }

    @Test
    void listenersHearChangesOnly() {
        assertEquals(Optional.empty(), sensor.brightness());
        assertHeardEvery(10, List.of("40%@0", "0%@20", "100%@30"), 40, 40, 0, 100, 100);
        assertEquals(Optional.of(Percent.FULL), sensor.brightness());
    }

    @Test
    void otherSensorsOfTheNodeAreIgnoredAndBadPayloadsGiveNoEventAndNoException() {
        sensor.payloadReceived(bus, SunSpotSensorType.TEMPERATURE.code(),
                SunSpotPayloads.encode(new TemperatureStatus(21.0)), T0);
        sensor.payloadReceived(bus, SunSpotSensorType.MOVEMENT.code(),
                SunSpotPayloads.encode(new MovementDetection(true)), T0);
        assertEquals(DeviceStatus.State.UNKNOWN, sensor.status().state(), "nothing of ours arrived yet");

        deliver(new byte[] {4, 1, 0, (byte) 150}, 0); // 150 %
        deliver(new byte[] {4, 1, 0, (byte) 0xFF}, 0); // 255 %, or -1 if signed
        deliver(new byte[] {4, 1, 0}, 0);
        deliver(SunSpotPayloads.encode(new TemperatureStatus(21.0)), 0);

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
}

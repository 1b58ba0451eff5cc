package org.tinysep.sunspot.temperature.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.OptionalDouble;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.device.support.testing.SunSpotDeviceTestSupport;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** Temperature Status payloads in, temperatures out, thinned by the dead band. */
class SunSpotTemperatureDeviceTest extends SunSpotDeviceTestSupport<SunSpotTemperatureDevice, Double> {

    SunSpotTemperatureDeviceTest() {
        super("SunSpotTemperature", SunSpotSensorType.TEMPERATURE.code(), SunSpotTemperatureDevice::new,
                celsius -> SunSpotPayloads.encode(new TemperatureStatus(celsius)));
        sensor.connect((src, celsius, at) -> hear(celsius, at));
    }

    @Test
    void listenersHearReadingsThatMoveByTheDeadBandFromTheLastOneTheyHeard() {
        assertEquals(OptionalDouble.empty(), sensor.celsius());
        // the node repeats itself every 10 s; 21.6 is 0.1 from 21.5 (the payload's resolution), 21.7 is 0.1 from 21.6
        // although 21.7 - 21.6 < 0.1 in binary floating point
        assertHeardEvery(10, List.of("21.5@0", "21.6@20", "21.7@40", "21.0@50"), 21.5, 21.5, 21.6, 21.6, 21.7, 21.0);
        assertEquals(21.0, sensor.celsius().orElseThrow(), 1e-9);
    }

    @Test
    void aWiderDeadBandHidesNoiseAndAnnouncesDriftOnceItAddsUp() {
        sensor.setParameter("deadbandCelsius", "0.5");
        feed(20.0, 0);
        feed(20.2, 10); // noise
        feed(19.8, 20);
        for (int i = 1; i <= 10; i++) {
            feed(20.0 + i * 0.1, 20 + i * 10); // slow drift upwards
        }
        assertEquals(List.of("20.0@0", "20.5@70", "21.0@120"), heard);
        assertEquals(21.0, sensor.celsius().orElseThrow(), 1e-9, "the provider always tells the latest reading");
    }

    @Test
    void aZeroDeadBandPassesEveryReadingOn() {
        sensor.setParameter("deadbandCelsius", "0");
        feedEvery(10, 19.0, 19.0);
        assertEquals(List.of("19.0@0", "19.0@10"), heard);
    }

    @Test
    void otherSensorsOfTheNodeAreIgnoredAndBadPayloadsGiveNoEventAndNoException() {
        sensor.payloadReceived(bus, SunSpotSensorType.LIGHT.code(), SunSpotPayloads.encode(new LightStatus(30)), T0);
        sensor.payloadReceived(bus, SunSpotSensorType.MOVEMENT.code(),
                SunSpotPayloads.encode(new MovementDetection(true, null)), T0);
        assertEquals(DeviceStatus.State.UNKNOWN, sensor.status().state(), "nothing of ours arrived yet");

        deliver(new byte[] {3, 1}, 0);
        deliver(new byte[] {(byte) 0xFF, 0, 0, 0}, 0);
        deliver(new byte[] {3, 1, 0x7F, 0}, 0); // 3251.2 °C
        deliver(SunSpotPayloads.encode(new LightStatus(30)), 0);

        assertEquals(List.of(), heard);
        assertTrue(sensor.celsius().isEmpty());
        assertEquals("4", parameter("rejectedPayloads"));
        assertEquals(DeviceStatus.State.ERROR, sensor.status().state());
        assertTrue(sensor.status().detail().startsWith("rejected payload: "), sensor.status().detail());

        feed(22.3, 5);
        assertEquals(List.of("22.3@5"), heard);
        assertEquals(DeviceStatus.State.ONLINE, sensor.status().state());
    }

    @Test
    void deadBandIsValidated() {
        assertEquals("0.1", parameter("deadbandCelsius"));
        for (String bad : new String[] {"-0.1", "warm", "", "NaN", "Infinity"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> sensor.setParameter("deadbandCelsius", bad));
            assertEquals("deadbandCelsius must be a number >= 0, was '" + bad + "'", e.getMessage());
        }
        assertEquals(0.1, sensor.deadband(), "unchanged after bad values");
        sensor.setParameter("deadbandCelsius", " 0.25 ");
        assertEquals(0.25, sensor.deadband());
        assertThrows(IllegalArgumentException.class, () -> sensor.setParameter("celsius", "20"));
    }
}

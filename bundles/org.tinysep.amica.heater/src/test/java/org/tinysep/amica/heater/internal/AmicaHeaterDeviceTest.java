package org.tinysep.amica.heater.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.actuator.base.testing.FakeBus;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.SpeakerControl;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.PlatformClock;
import org.tinysep.device.support.RecordingLogs;

/**
 * This bundle's wiring of the shared actuator device (whose model, confirmation and errors are tested in
 * {@code org.tinysep.amica.actuator.base}): HeaterControl reports in, {@code potencyChanged} out; {@code setPotency} and
 * the {@code potency} parameter send HeaterControl ({@code 5 8 0 A}).
 */
class AmicaHeaterDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    private final FakeBus bus = new FakeBus("1.21", "heater");
    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final AmicaHeaterDevice device = new AmicaHeaterDevice(new DriverContext(null, "d", AmicaHeaterDriver.NAME, logs.reporter(),
            new PlatformClock(() -> T0)), bus);
    private final List<String> heard = new ArrayList<>();

    AmicaHeaterDeviceTest() {
        device.connect((source, value, at) -> heard.add((source == device ? "" : "wrong source ") + value + "@"
                + (at.getEpochSecond() - T0.getEpochSecond())));
    }

    private void receive(AmicaPayload payload, int second) {
        device.payloadReceived(bus, AmicaPayloads.encode(payload), T0.plusSeconds(second));
    }

    @Test
    void itsHeaterControlReportsAreItsValueAndOtherControlsAreNot() {
        receive(new HeaterControl(30), 0);
        receive(new LightControl(90), 1);
        receive(new SpeakerControl(80), 2);
        receive(new HeaterControl(75), 3);

        assertEquals(List.of("30%@0", "75%@3"), heard);
        assertEquals(Optional.of(Percent.of(75)), device.potency());
        assertEquals("Heater 1.21", device.name());
    }

    @Test
    void setPotencyAndThePotencyParameterSendHeaterControl() {
        device.setPotency(Percent.of(40));
        device.setParameter("potency", "65");

        assertEquals(2, bus.sent.size());
        assertArrayEquals(new byte[] {5, 8, 0, 40}, bus.sent.get(0));
        assertArrayEquals(new byte[] {5, 8, 0, 65}, bus.sent.get(1));
        assertThrows(IllegalArgumentException.class, () -> device.setParameter("volume", "10"));
    }
}

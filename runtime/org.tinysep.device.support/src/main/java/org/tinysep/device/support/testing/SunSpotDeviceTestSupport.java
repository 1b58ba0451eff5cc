package org.tinysep.device.support.testing;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BiFunction;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.Parameter;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.RecordingLogs;

/**
 * The fixture of a Sun SPOT sensor device's unit test, written once: the device under test ({@link #sensor}) built
 * without a framework on a {@link FakeSunSpotBus} and a {@link TestPlatform} (recorded logs, a clock fixed at
 * {@link #T0}); payloads of the sensor's own type are delivered with {@link #deliver}, and listeners record what they
 * hear with {@link #hear}.
 *
 * @param <D> the device under test
 */
public abstract class SunSpotDeviceTestSupport<D extends Device & BusRadioSunSpotListener> {

    protected static final Instant T0 = TestPlatform.T0;

    protected final FakeSunSpotBus bus = new FakeSunSpotBus();
    private final TestPlatform platform = new TestPlatform();
    protected final RecordingLogs logs = platform.logs;
    /** What the test's listener heard, in order. */
    protected final List<Object> heard = new ArrayList<>();
    protected final D sensor;
    private final int sensorType;

    /**
     * @param driverName the device's driver name
     * @param sensorType the Sun SPOT sensor type code of its payloads
     * @param device     makes the device, e.g. {@code SunSpotLightDevice::new}
     */
    protected SunSpotDeviceTestSupport(String driverName, int sensorType,
            BiFunction<DriverContext, BusRadioSunSpotProvider, D> device) {
        this.sensorType = sensorType;
        this.sensor = device.apply(platform.context(driverName), bus);
    }

    /** Delivers one payload of the sensor's own type {@code second}s after {@link #T0}. */
    protected final void deliver(byte[] payload, int second) {
        sensor.payloadReceived(bus, sensorType, payload, T0.plusSeconds(second));
    }

    /** Records {@code value@s}, s being the seconds since {@link #T0}: for listeners of changing values. */
    protected final void hear(Object value, Instant at) {
        heard.add(value + "@" + (at.getEpochSecond() - T0.getEpochSecond()));
    }

    /** @return the value of one of the sensor's parameters */
    protected final String parameter(String key) {
        return sensor.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow(() -> new AssertionError(sensor.name() + " has no parameter " + key));
    }
}

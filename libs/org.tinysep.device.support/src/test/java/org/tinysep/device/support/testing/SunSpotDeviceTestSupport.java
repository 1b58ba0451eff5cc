package org.tinysep.device.support.testing;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BiFunction;
import java.util.function.Function;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;

/**
 * The fixture of a Sun SPOT sensor device's unit test, written once: the device under test ({@link #sensor}) built
 * without a framework on a {@link FakeSunSpotBus} and a {@link TestPlatform} (recorded logs, a clock fixed at
 * {@link #T0}); payloads of the sensor's own type are delivered with {@link #deliver}, readings of its value with
 * {@link #feed} or, a node reporting at a steady interval, {@link #feedEvery}, and listeners record what they hear
 * with {@link #hear}.
 *
 * @param <D> the device under test
 * @param <V> the value of the sensor's payload, e.g. a light sensor's percent
 */
public abstract class SunSpotDeviceTestSupport<D extends Device & BusRadioSunSpotListener, V> {

    protected static final Instant T0 = TestPlatform.T0;

    protected final FakeSunSpotBus bus = new FakeSunSpotBus();
    private final TestPlatform platform = new TestPlatform();
    protected final RecordingLogs logs = platform.logs;
    /** What the test's listener heard, in order. */
    protected final List<Object> heard = new ArrayList<>();
    protected final D sensor;
    private final int sensorType;
    private final Function<V, byte[]> payload;

    /**
     * @param driverName the device's driver name
     * @param sensorType the Sun SPOT sensor type code of its payloads
     * @param device     makes the device, e.g. {@code SunSpotLightDevice::new}
     * @param payload    encodes one reading, e.g. {@code p -> SunSpotPayloads.encode(new LightStatus(p))}
     */
    protected SunSpotDeviceTestSupport(String driverName, int sensorType,
            BiFunction<DriverContext, BusRadioSunSpotProvider, D> device, Function<V, byte[]> payload) {
        this.sensorType = sensorType;
        this.payload = payload;
        this.sensor = device.apply(platform.context(driverName), bus);
    }

    /** Delivers one reading {@code second}s after {@link #T0}. */
    protected final void feed(V value, int second) {
        deliver(payload.apply(value), second);
    }

    /** Delivers the readings in order, the first at {@link #T0}, each next one {@code interval} seconds later. */
    @SafeVarargs
    protected final void feedEvery(int interval, V... values) {
        for (int i = 0; i < values.length; i++) {
            feed(values[i], i * interval);
        }
    }

    /** Delivers one payload of the sensor's own type {@code second}s after {@link #T0}. */
    protected final void deliver(byte[] payload, int second) {
        sensor.payloadReceived(bus, sensorType, payload, T0.plusSeconds(second));
    }

    /**
     * What every report owes, checked once: the readings delivered as by {@link #feedEvery}, listeners heard
     * {@code expected} (as {@link #hear} writes it), the {@code lastUpdate} parameter is the last reading's time and the
     * sensor is ONLINE.
     */
    @SafeVarargs
    protected final void assertHeardEvery(int interval, List<String> expected, V... readings) {
        feedEvery(interval, readings);
        check(expected, heard, "what the listener heard");
        check(T0.plusSeconds((readings.length - 1L) * interval).toString(), parameter("lastUpdate"), "lastUpdate");
        check(DeviceStatus.State.ONLINE, sensor.status().state(), "the status after a good report");
    }

    /** This library has no JUnit at compile time: a failed check is an {@link AssertionError}, as JUnit's. */
    private static void check(Object expected, Object actual, String what) {
        if (!expected.equals(actual)) {
            throw new AssertionError(what + ": expected " + expected + " but was " + actual);
        }
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

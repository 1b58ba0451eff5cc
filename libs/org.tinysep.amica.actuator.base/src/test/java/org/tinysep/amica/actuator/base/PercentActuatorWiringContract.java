package org.tinysep.amica.actuator.base;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.BiFunction;
import java.util.function.IntFunction;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.actuator.base.testing.FakeBus;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.SpeakerControl;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.testing.TestPlatform;

/**
 * The unit test of one actuator bundle's wiring of {@link PercentActuatorDevice}, written once for the dimmable light,
 * the heater and the speaker (the shared model, confirmation and errors are tested in
 * {@code PercentActuatorDeviceTest}): its own control's reports are its value and reach its listeners, the other
 * AmICA percent controls' are not; {@code setLevel} and its parameter send its control ({@code 5 code 0 A}), the other
 * actuators' parameters are refused. A bundle's test (shared through this module's test jar) names its device and its
 * control, and connects a listener that calls {@link #hear}.
 *
 * @param <D> the bundle's device
 */
public abstract class PercentActuatorWiringContract<D extends PercentActuatorDevice<?, ?>> {

    /** The three AmICA percent controls by their actuators' parameter keys. */
    private static final Map<String, IntFunction<AmicaPayload>> CONTROLS = Map.of("brightness", LightControl::new,
            "potency", HeaterControl::new, "volume", SpeakerControl::new);
    private static final Instant T0 = TestPlatform.T0;

    private final TestPlatform platform = new TestPlatform();
    private final FakeBus bus;
    private final List<String> heard = new ArrayList<>();
    private final String label;
    private final String key;
    private final int code;
    /** The device under test, on a fake bus of node {@code 1.21}. */
    protected final D device;

    /**
     * @param nodeType   the node's type name, e.g. {@code "heater"}
     * @param driverName the device's driver name
     * @param make       makes the device, e.g. {@code AmicaHeaterDevice::new}
     * @param label      the start of the device's name, e.g. {@code "Heater"}
     * @param key        its value's parameter key, e.g. {@code "potency"}: its control is the one of that key
     * @param code       its control's payload code, the second byte of {@code 5 code 0 A}
     */
    protected PercentActuatorWiringContract(String nodeType, String driverName,
            BiFunction<DriverContext, BusRadioAmicaProvider, D> make, String label, String key, int code) {
        this.bus = new FakeBus("1.21", nodeType);
        this.label = label;
        this.key = key;
        this.code = code;
        this.device = make.apply(platform.context(driverName), bus);
    }

    /** The test's listener: records {@code value@s}, s being the seconds since T0, and whether the source is wrong. */
    protected final void hear(Object source, Percent percent, Instant at) {
        heard.add((source == device ? "" : "wrong source ") + percent + "@" + (at.getEpochSecond() - T0.getEpochSecond()));
    }

    @Test
    void itsControlReportsAreItsValueAndOtherControlsAreNot() {
        receive(CONTROLS.get(key).apply(30), 0);
        int second = 0;
        for (String other : CONTROLS.keySet().stream().filter(k -> !k.equals(key)).sorted().toList()) {
            receive(CONTROLS.get(other).apply(90 - 10 * second), ++second);
        }
        receive(CONTROLS.get(key).apply(75), 3);

        assertEquals(List.of("30%@0", "75%@3"), heard);
        assertEquals(Optional.of(Percent.of(75)), device.level());
        assertEquals(label + " 1.21", device.name());
    }

    @Test
    void setLevelAndItsParameterSendItsControl() {
        device.setLevel(Percent.of(40));
        device.setParameter(key, "65");

        assertEquals(2, bus.sent.size());
        assertArrayEquals(new byte[] {5, (byte) code, 0, 40}, bus.sent.get(0));
        assertArrayEquals(new byte[] {5, (byte) code, 0, 65}, bus.sent.get(1));
        for (String other : CONTROLS.keySet()) {
            if (!other.equals(key)) {
                assertThrows(IllegalArgumentException.class, () -> device.setParameter(other, "10"), other);
            }
        }
    }

    private void receive(AmicaPayload payload, int second) {
        device.payloadReceived(bus, AmicaPayloads.encode(payload), T0.plusSeconds(second));
    }
}

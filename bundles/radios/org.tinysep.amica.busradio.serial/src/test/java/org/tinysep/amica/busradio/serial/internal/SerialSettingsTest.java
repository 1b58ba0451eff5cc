package org.tinysep.amica.busradio.serial.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.reflect.Proxy;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Configuration values as FileInstall delivers them (text), checked without ever failing the driver. */
class SerialSettingsTest {

    /**
     * A config the way DS builds it: text values converted on each call, a ComponentException-like failure when
     * the text is no number, the default when the key is absent.
     */
    private static BusRadioSerialConfig config(Map<String, String> values) {
        return (BusRadioSerialConfig) Proxy.newProxyInstance(SerialSettingsTest.class.getClassLoader(),
                new Class<?>[] {BusRadioSerialConfig.class}, (proxy, method, args) -> {
                    String v = values.get(method.getName());
                    return switch (method.getName()) {
                        case "port" -> v;
                        case "baudRate" -> v == null ? SerialSettings.DEFAULT_BAUD_RATE : Integer.parseInt(v.trim());
                        case "reopenSeconds" -> v == null ? SerialSettings.DEFAULT_REOPEN_SECONDS
                                : Integer.parseInt(v.trim());
                        default -> throw new UnsupportedOperationException(method.getName());
                    };
                });
    }

    private static SerialSettings settings(Map<String, String> values) {
        Map<String, Object> raw = new HashMap<>(values);
        raw.put("service.pid", "org.tinysep.amica.busradio.serial~kitchen");
        return SerialSettings.of(config(values), raw);
    }

    @Test
    void defaultsAndTheDriverNameFollowThePort() {
        SerialSettings s = settings(Map.of("port", " /dev/ttyUSB0 "));
        assertEquals(new SerialSettings("/dev/ttyUSB0", 115200, Duration.ofSeconds(2),
                "org.tinysep.amica.busradio.serial~kitchen", List.of()), s);
        assertEquals("BusRadioAmicaSerial /dev/ttyUSB0", s.driverName());
    }

    @Test
    void badNumbersFallBackToTheirDefaultsWithOneSentenceEach() {
        SerialSettings s = settings(Map.of("port", "/dev/ttyACM0", "baudRate", "fast", "reopenSeconds", "-3"));
        assertEquals(115200, s.baudRate());
        assertEquals(Duration.ofSeconds(2), s.reopenEvery());
        assertEquals(List.of("baudRate 'fast' is not a whole number; using 115200",
                "reopenSeconds -3 must be positive; using 2"), s.problems());
    }

    @Test
    void aMissingPortIsAProblemAndTheNamePointsAtTheConfiguration() {
        SerialSettings s = settings(Map.of("baudRate", "9600"));
        assertEquals(null, s.port());
        assertEquals(9600, s.baudRate());
        assertEquals(List.of("no serial port configured: set key 'port' (e.g. port=/dev/ttyUSB0)"), s.problems());
        assertEquals("BusRadioAmicaSerial (no port, org.tinysep.amica.busradio.serial~kitchen)", s.driverName());
    }
}

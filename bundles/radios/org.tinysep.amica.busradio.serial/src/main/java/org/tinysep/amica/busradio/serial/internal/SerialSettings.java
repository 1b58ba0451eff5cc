package org.tinysep.amica.busradio.serial.internal;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.IntSupplier;
import org.tinysep.device.support.health.NodePolicy;

/**
 * The configuration of one serial port, checked: a bad value never stops the driver. A missing port leaves the
 * driver without a link (and says so); a bad baud rate or reopen interval falls back to its default. Each
 * problem is one sentence for the event log.
 *
 * @param port      the port path, or null when none is configured
 * @param configPid the configuration's pid, naming a driver that has no port
 */
record SerialSettings(String port, int baudRate, Duration reopenEvery, String configPid, List<String> problems) {

    static final int DEFAULT_BAUD_RATE = 115200;
    static final int DEFAULT_REOPEN_SECONDS = 2;

    SerialSettings {
        problems = List.copyOf(problems);
    }

    static SerialSettings of(BusRadioSerialConfig config, Map<String, ?> raw) {
        List<String> problems = new ArrayList<>();
        String port = null;
        try {
            port = config.port();
        } catch (RuntimeException e) {
            // no value: handled below
        }
        if (port == null || port.isBlank()) {
            port = null;
            problems.add("no serial port configured: set key 'port' (e.g. port=/dev/ttyUSB0)");
        } else {
            port = port.strip();
        }
        int baud = positive("baudRate", config::baudRate, raw, DEFAULT_BAUD_RATE, problems);
        int reopen = positive("reopenSeconds", config::reopenSeconds, raw, DEFAULT_REOPEN_SECONDS, problems);
        Object pid = raw.get("service.pid");
        return new SerialSettings(port, baud, Duration.ofSeconds(reopen), pid == null ? "?" : pid.toString(),
                problems);
    }

    private static int positive(String key, IntSupplier typed, Map<String, ?> raw, int fallback,
            List<String> problems) {
        int value;
        try {
            value = typed.getAsInt();
        } catch (RuntimeException e) { // DS throws when the configured text is no number
            problems.add(key + " '" + raw.get(key) + "' is not a whole number; using " + fallback);
            return fallback;
        }
        if (value <= 0) {
            problems.add(key + " " + value + " must be positive; using " + fallback);
            return fallback;
        }
        return value;
    }

    /**
     * The health and capacity settings (sensor health, node cap); a bad value is a problem line and its default.
     */
    static NodePolicy policy(BusRadioSerialConfig config, Map<String, ?> raw, List<String> problems) {
        NodePolicy d = NodePolicy.DEFAULT;
        int silent = positive("silentAfterIntervals", config::silentAfterIntervals, raw, d.silentAfterIntervals(),
                problems);
        int max = positive("maxNodes", config::maxNodes, raw, d.maxNodes(), problems);
        int low;
        try {
            low = config.lowBatteryMillivolts();
        } catch (RuntimeException e) {
            problems.add("lowBatteryMillivolts '" + raw.get("lowBatteryMillivolts") + "' is not a whole number; using "
                    + d.lowBatteryMillivolts());
            low = d.lowBatteryMillivolts();
        }
        return NodePolicy.of(silent, low, max, problems);
    }

    /** @return {@code BusRadioAmicaSerial <port>}, or a name that points at the configuration without a port */
    String driverName() {
        return AmicaSerialDriver.NAME + " " + (port != null ? port : "(no port, " + configPid + ")");
    }
}

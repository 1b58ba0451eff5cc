package org.tinysep.itests.mqtt;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import org.ops4j.pax.exam.Option;
import org.tinysep.itests.web.WebTestSupport;

/**
 * The framework of the MQTT bridge's and the central board's tests: the web console, the alert service, Sensor
 * Health, the bridge and the board (both idle until a test configures a broker), and the Mosquitto test support
 * bundle (the real broker, certificates, a recording client).
 */
public abstract class MqttBridgeSupport extends WebTestSupport {

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts", "org.tinysep.sensorhealth", "org.tinysep.mqtt");
    }

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.add(reactorBundle("org.tinysep.testsupport.mqtt", 5));
        o.add(reactorBundle("org.tinysep.mqtt.board", 5));
        return o;
    }

    /**
     * @return a new folder holding {@code <flat>.key} (owner-only) with {@code key}: the board's flatKeyDir, and
     *         {@code dir/<flat>.key} the flat's bridge's keyFile (issue 25 item 2)
     */
    public static Path flatKeyDir(String flat, String key) {
        try {
            Path dir = Files.createTempDirectory("tinysep-flat-keys");
            Path f = Files.writeString(dir.resolve(flat + ".key"), key + "\n");
            Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-------"));
            return dir;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.alerts", Map.of("summaryTime", "", "timeZone", "UTC"));
        return configs;
    }
}

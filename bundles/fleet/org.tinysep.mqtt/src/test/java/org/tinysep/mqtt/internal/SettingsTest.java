package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;

class SettingsTest {

    private static final Path VAR = Path.of("/var/lib/tinysep");

    @Test
    void idleWithoutABrokerAndDefaultsUnderTheStateFolder() {
        Settings s = Settings.parse(Map.of(), VAR);
        assertFalse(s.configured());
        assertEquals(VAR.resolve("secrets/mqtt.password"), s.passwordFile());
        assertEquals(VAR.resolve("mqtt"), s.queueDir());
        assertEquals("tinysep", s.topicPrefix());
        assertEquals("homeassistant", s.discoveryPrefix());
    }

    @Test
    void aConfiguredBridgeNeverShowsItsPassword() {
        Settings s = Settings.parse(Map.of("brokerUrl", "ssl://broker:8883", "flatId", "flat-7", "username", "u"),
                VAR);
        assertTrue(s.configured());
        assertTrue(s.tls());
        assertEquals("ssl://broker:8883 as flat-7 (user u), topics tinysep/flat-7/…", s.redacted());
    }

    @Test
    void refusesWhatWouldBreakTopicsInWords() {
        assertTrue(refused(Map.of("brokerUrl", "http://x")).contains("tcp://host:port or ssl://host:port"));
        assertTrue(refused(Map.of("flatId", "a/b")).contains("flatId 'a/b' may only hold"));
        assertTrue(refused(Map.of("flatId", "a+")).contains("may only hold"));
        assertTrue(refused(Map.of("topicPrefix", "x/#")).contains("topicPrefix"));
        assertTrue(refused(Map.of("heartbeatSeconds", "0")).contains("heartbeatSeconds must be 1..86400"));
        assertTrue(refused(Map.of("pollSeconds", "soon")).contains("whole number"));
        assertTrue(refused(Map.of("commands.ack", "anyone")).contains("commands.ack must be off, signed or unsigned"));
        assertTrue(refused(Map.of("allowAnonymous", "yes")).contains("allowAnonymous must be true or false"));
    }

    @Test
    void safeDefaultsForWhoMayAct() {
        Settings s = Settings.parse(Map.of("brokerUrl", "tcp://b:1883"), VAR);
        assertTrue(s.anonymous());
        assertFalse(s.allowAnonymous());
        assertEquals(CommandPolicy.SIGNED, s.ackCommands());
        assertEquals(CommandPolicy.OFF, s.actuatorCommands());
        assertEquals(VAR.resolve("secrets/mqtt.key"), s.keyFile());
        assertEquals(300, s.commandMaxAgeSeconds());
    }

    @Test
    void topicLevelsAreSanitised() {
        assertEquals("a_b_c_d_e", Topics.level("a+b#c/d e"));
        Topics t = new Topics("tinysep", "f", "homeassistant");
        assertEquals("tinysep/f/device/x_y/state", t.deviceState("x/y"));
        assertEquals("homeassistant/light/tinysep_f_u1/config", t.discoveryConfig("light", "u1"));
    }

    private static String refused(Map<String, String> p) {
        return assertThrows(IllegalArgumentException.class, () -> Settings.parse(p, VAR)).getMessage();
    }
}

package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.slf4j.LoggerFactory;

/** Issue 25 item 2: no login ⇒ no connection (unless allowAnonymous, then loudly); the key and unsigned commands. */
class BridgeChecksTest {

    @TempDir
    Path var;
    final List<String> problems = new ArrayList<>();

    private boolean allowed(Map<String, String> c) {
        return BridgeChecks.loginAllowed(Settings.parse(c, var), problems::add, LoggerFactory.getLogger("test"));
    }

    @Test
    void anonymousIsRefusedWithMonitoringReduced() {
        assertFalse(allowed(Map.of("brokerUrl", "tcp://127.0.0.1:1883", "flatId", "flat-7")));
        assertEquals(1, problems.size());
        assertTrue(problems.get(0).startsWith("Monitoring reduced: the MQTT bridge of flat flat-7 does not connect"),
                problems.get(0));
        assertTrue(problems.get(0).contains("allowAnonymous=true"), problems.get(0));
    }

    @Test
    void anonymousWithTheOverrideConnectsAndWarnsLoudly() {
        assertTrue(allowed(Map.of("brokerUrl", "tcp://127.0.0.1:1883", "flatId", "flat-7", "allowAnonymous", "true")));
        assertEquals(1, problems.size());
        assertTrue(problems.get(0).contains("WITHOUT a login (allowAnonymous=true): anyone who can reach this broker"),
                problems.get(0));
    }

    @Test
    void aUserOrAClientCertificateIsALogin() {
        assertTrue(allowed(Map.of("brokerUrl", "tcp://127.0.0.1:1883", "username", "flat-7")));
        assertTrue(allowed(Map.of("brokerUrl", "ssl://127.0.0.1:8883", "keyStore", "/etc/flat.p12")));
        assertEquals(List.of(), problems);
    }

    @Test
    void aMissingKeyAnOpenKeyAndUnsignedCommandsAreProblems() throws Exception {
        Settings s = Settings.parse(Map.of("brokerUrl", "tcp://127.0.0.1:1883", "username", "u",
                "commands.actuators", "unsigned"), var);
        BridgeChecks.key(s, FlatKey.read(s.keyFile()), problems::add, LoggerFactory.getLogger("test"));
        assertEquals(2, problems.size(), problems.toString());
        assertTrue(problems.get(0).startsWith("Monitoring reduced: the MQTT bridge of flat flat has no key"),
                problems.get(0));
        assertTrue(problems.get(1).contains("commands.actuators=unsigned"), problems.get(1));

        Path key = Files.createDirectories(var.resolve("secrets")).resolve("mqtt.key");
        Files.writeString(key, "0123456789abcdef0123456789abcdef\n");
        Files.setPosixFilePermissions(key, PosixFilePermissions.fromString("rw-r-----"));
        FlatKey k = FlatKey.read(key);
        assertEquals(32, k.key().length);
        assertTrue(k.warning().contains("chmod 600"), k.warning());
        Files.writeString(key, "short\n");
        assertTrue(FlatKey.read(key).missing().contains("at least 16"), FlatKey.read(key).missing());
    }
}

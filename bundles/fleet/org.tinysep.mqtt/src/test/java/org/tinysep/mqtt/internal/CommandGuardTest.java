package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.json.JsonSignature;
import org.tinysep.testsupport.mqtt.Signed;

/**
 * Issue 25 item 2: who may act over MQTT. Acknowledgements only signed with the flat's key (by default),
 * actuators off (by default); unsigned, badly signed, stale and replayed commands refused, counted, the first one
 * a PROBLEM. Signed with the test support's own HMAC code: the wire format, not this bundle's code, is checked.
 */
class CommandGuardTest {

    static final String KEY = "flat-7-key-0123456789abcdef";
    static final String ACK = "tinysep/flat-7/command/alert/3/ack";
    static final String LIGHT = "tinysep/flat-7/command/device/light1";
    final Instant now = Instant.parse("2026-11-28T10:00:00Z");
    final List<String> problems = new ArrayList<>();

    CommandGuard guard(Map<String, String> config) {
        Settings s = Settings.parse(config, Path.of("/var/tinysep"));
        return new CommandGuard(new Topics("tinysep", "flat-7", ""), s, KEY.getBytes(StandardCharsets.UTF_8), null,
                Clock.fixed(now, ZoneOffset.UTC), problems::add);
    }

    static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    String signedAck(Instant at) {
        return Signed.sign(KEY, ACK, Signed.commandBody("\"by\":\"Eva\"", at));
    }

    @Test
    void aSignedAcknowledgementIsTakenOnlyOnce() {
        CommandGuard g = guard(Map.of("flatId", "flat-7"));
        String ack = signedAck(now.minusSeconds(20));
        CommandGuard.Verdict v = g.check(ACK, bytes(ack));
        assertNull(v.refusal());
        String command = new String(v.command(), StandardCharsets.UTF_8);
        assertTrue(command.startsWith("{\"by\":\"Eva\",\"at\":") && !command.contains("sig"), command);
        assertTrue(g.check(ACK, bytes(ack)).refusal().contains("already used (a replayed command)"));
        assertEquals(1, g.refused());
    }

    @Test
    void unsignedBadlySignedStaleAndMovedCommandsAreRefusedAndCounted() {
        CommandGuard g = guard(Map.of("flatId", "flat-7"));
        assertTrue(g.check(ACK, bytes("{\"by\":\"Mallory\"}")).refusal().startsWith("unsigned command refused"));
        assertTrue(g.check(ACK, bytes(Signed.sign("another-key-0123456789", ACK, Signed.commandBody("\"by\":\"M\"", now))))
                .refusal().startsWith("badly signed command refused"));
        assertTrue(g.check(ACK, bytes(Signed.sign(KEY, "tinysep/flat-7/command/alert/4/ack",
                Signed.commandBody("\"by\":\"M\"", now)))).refusal().startsWith("badly signed"));
        assertTrue(g.check(ACK, bytes(signedAck(now.minusSeconds(301)))).refusal().contains("301 s away"));
        assertTrue(g.check(ACK, bytes(Signed.sign(KEY, ACK, "{\"by\":\"M\"}"))).refusal().contains("no time 'at'"));
        assertEquals(5, g.refused());
        assertEquals(1, problems.size(), "the first refusal is a PROBLEM, later ones only counted: " + problems);
        assertTrue(problems.get(0).contains("refused a command on " + ACK + ": unsigned command refused"),
                problems.get(0));
    }

    @Test
    void actuatorsAreOffByDefaultAndCanBeSignedOrUnsigned() {
        String on = "{\"parameter\":\"on\",\"value\":true}";
        assertTrue(guard(Map.of("flatId", "flat-7")).check(LIGHT, bytes(Signed.sign(KEY, LIGHT,
                Signed.commandBody("\"parameter\":\"on\",\"value\":true", now)))).refusal()
                .contains("switched off in flat flat-7 (commands.actuators=off)"));
        CommandGuard signed = guard(Map.of("flatId", "flat-7", "commands.actuators", "signed"));
        assertTrue(signed.check(LIGHT, bytes(on)).refusal().startsWith("unsigned command refused"));
        assertNull(signed.check(LIGHT, bytes(Signed.sign(KEY, LIGHT,
                Signed.commandBody("\"parameter\":\"on\",\"value\":true", now)))).refusal());
        assertNull(guard(Map.of("flatId", "flat-7", "commands.actuators", "unsigned")).check(LIGHT, bytes("ON"))
                .refusal());
        assertTrue(guard(Map.of("flatId", "flat-7", "commands.ack", "off")).check(ACK, bytes(signedAck(now)))
                .refusal().contains("commands.ack=off"));
    }

    @Test
    void theBridgeSignsWhatTheBoardChecks() {
        String json = "{\"id\":\"3\",\"state\":\"OPEN\",\"seq\":4}";
        String signed = JsonSignature.sign(KEY.getBytes(StandardCharsets.UTF_8), "tinysep/flat-7/alert/3", json);
        assertEquals(Signed.sign(KEY, "tinysep/flat-7/alert/3", json), signed);
        assertEquals(json, JsonSignature.check(KEY.getBytes(StandardCharsets.UTF_8), "tinysep/flat-7/alert/3", signed)
                .unsigned());
    }
}

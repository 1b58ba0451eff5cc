package org.tinysep.mqtt.internal;

import java.nio.charset.StandardCharsets;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Consumer;
import java.util.regex.Pattern;
import org.tinysep.json.JsonSignature;

/**
 * Who may act through MQTT (docs/mqtt.md, "Commands: who may act"). MQTT carries no sender, so a command proves its
 * origin by its signature: HMAC-SHA256 with the flat's key ({@link FlatKey}), with {@code at} (ISO-8601, within
 * {@code commands.maxAgeSeconds} of this computer's clock) and a {@code nonce} seen only once in that time (no
 * replay). {@code commands.ack} and {@code commands.actuators} say per kind: off, signed or unsigned. A refused
 * command is counted; the first one of this bridge is a PROBLEM in the event log, later ones only counted. Used on
 * the bridge's thread only.
 */
final class CommandGuard {

    /** Nonces remembered at most (the oldest go first: a flood cannot grow the memory). */
    static final int MAX_NONCES = 10_000;
    private static final Pattern NONCE = Pattern.compile("[A-Za-z0-9_-]{8,64}");

    /** @param refusal null when the command may be carried out; {@code command} is then its payload without sig */
    record Verdict(String refusal, byte[] command) {
    }

    private final String flat;
    private final String commandPrefix;
    private final byte[] key;
    private final String noKey;
    private final Settings settings;
    private final Clock wall;
    private final Consumer<String> problem;
    private final Map<String, Instant> nonces = new LinkedHashMap<>();
    private long refused;

    /**
     * @param key     the flat's key, null when there is none ({@code noKey} says why): signed commands are refused
     * @param wall    this computer's clock (not the platform's, which may be simulated)
     * @param problem records a PROBLEM in the event log
     */
    CommandGuard(Topics topics, Settings settings, byte[] key, String noKey, Clock wall, Consumer<String> problem) {
        this.flat = topics.flatId();
        this.commandPrefix = topics.commandPrefix();
        this.settings = settings;
        this.key = key;
        this.noKey = noKey;
        this.wall = wall;
        this.problem = problem;
    }

    Verdict check(String topic, byte[] payload) {
        String rest = topic.startsWith(commandPrefix) ? topic.substring(commandPrefix.length()) : "";
        boolean ack = rest.startsWith("alert/");
        CommandPolicy policy = ack ? settings.ackCommands() : rest.startsWith("device/")
                ? settings.actuatorCommands() : CommandPolicy.UNSIGNED; // unknown topics: Commands refuses them
        String what = ack ? "acknowledgements" : "switching devices";
        String key = ack ? "commands.ack" : "commands.actuators";
        if (policy == CommandPolicy.OFF) {
            return refuse(topic, what + " over MQTT are switched off in flat " + flat + " (" + key + "=off)");
        }
        String text = new String(payload, StandardCharsets.UTF_8);
        JsonSignature.Checked c = JsonSignature.check(this.key, topic, text);
        if (!c.signed()) {
            return policy == CommandPolicy.UNSIGNED ? new Verdict(null, payload)
                    : refuse(topic, "unsigned command refused: " + what + " must be signed with the flat's key ("
                            + key + "=signed; docs/mqtt.md)");
        }
        if (this.key == null) {
            return refuse(topic, "signed command refused: flat " + flat + " has no key to check it (" + noKey + ")");
        }
        if (!c.valid()) {
            return refuse(topic, "badly signed command refused: the signature does not match flat " + flat
                    + "'s key and this topic");
        }
        String stale = fresh(c.unsigned());
        return stale != null ? refuse(topic, stale)
                : new Verdict(null, c.unsigned().getBytes(StandardCharsets.UTF_8));
    }

    /** @return null when the signed command's {@code at} is recent and its {@code nonce} new, else why not */
    private String fresh(String json) {
        Map<String, Object> o;
        try {
            o = Commands.object(json);
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
        Instant now = wall.instant();
        Instant at;
        try {
            at = o.get("at") instanceof String s ? Instant.parse(s) : null;
        } catch (DateTimeParseException e) {
            at = null;
        }
        if (at == null) {
            return "signed command refused: it has no time 'at' (ISO-8601, e.g. \"" + now + "\")";
        }
        long age = Math.abs(Duration.between(at, now).getSeconds());
        if (age > settings.commandMaxAgeSeconds()) {
            return "signed command refused: sent at " + at + ", " + age + " s away from this computer's clock "
                    + now + " (at most " + settings.commandMaxAgeSeconds() + " s, commands.maxAgeSeconds): a replay or a"
                    + " clock that is wrong";
        }
        if (!(o.get("nonce") instanceof String nonce) || !NONCE.matcher(nonce).matches()) {
            return "signed command refused: it needs a 'nonce' of 8 to 64 letters or digits, new for each command";
        }
        forgetOld(now);
        if (nonces.containsKey(nonce)) {
            return "signed command refused: its nonce " + nonce + " was already used (a replayed command)";
        }
        nonces.put(nonce, at);
        return null;
    }

    private void forgetOld(Instant now) {
        Instant limit = now.minusSeconds(2L * settings.commandMaxAgeSeconds());
        for (Iterator<Instant> it = nonces.values().iterator(); it.hasNext();) {
            Instant at = it.next();
            if (at.isBefore(limit) || nonces.size() >= MAX_NONCES) {
                it.remove();
            }
        }
    }

    private Verdict refuse(String topic, String why) {
        refused++;
        if (refused == 1) {
            problem.accept("MQTT bridge of flat " + flat + " refused a command on " + topic + ": " + why
                    + ". Someone on the broker tried to act on this flat without the flat's key. Further"
                    + " refusals are only counted (parameter refusedCommandsUnauthorised of the MqttBridge device).");
        }
        return new Verdict(why, null);
    }

    long refused() {
        return refused;
    }
}

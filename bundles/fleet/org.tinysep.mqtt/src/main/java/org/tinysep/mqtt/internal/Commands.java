package org.tinysep.mqtt.internal;

import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.Map;
import java.util.function.Supplier;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.device.Device;
import org.tinysep.json.JsonException;
import org.tinysep.json.JsonReader;
import org.tinysep.json.JsonWriter;

/**
 * Checks and carries out one incoming command, validated like the shell's {@code tinysep:set} and
 * {@code tinysep:ack}: the device's own {@link Device#setParameter} decides on the value, the alert service on the
 * acknowledgement. Only the actuator parameter of a light, heater or speaker may be set over MQTT. Never throws:
 * every refusal is a result in plain words.
 */
final class Commands {

    record Result(boolean accepted, String reason) {
    }

    /** The longest command payload read, in characters. */
    static final int MAX_PAYLOAD = 16 * 1024;

    private final Topics topics;
    private final DeviceScan scan;
    private final Supplier<AlertService> alerts;

    Commands(Topics topics, DeviceScan scan, Supplier<AlertService> alerts) {
        this.topics = topics;
        this.scan = scan;
        this.alerts = alerts;
    }

    Message result(String topic, Result r, Instant at) {
        return Message.transientMessage(topics.commandResult(), JsonWriter.writePlain(JsonWriter.object(
                "topic", topic, "accepted", r.accepted(), "reason", r.reason(), "at", at)));
    }

    Result handle(String topic, byte[] payload) {
        try {
            String text = utf8(payload);
            String rest = topic.startsWith(topics.commandPrefix()) ? topic.substring(topics.commandPrefix().length())
                    : "";
            if (rest.startsWith("device/") && rest.indexOf('/', 7) < 0) {
                return device(rest.substring(7), text);
            }
            if (rest.startsWith("alert/") && rest.endsWith("/ack")) {
                return ack(rest.substring(6, rest.length() - 4), text);
            }
            return no("unknown command topic " + topic + "; commands go to command/device/<uid> or "
                    + "command/alert/<id>/ack");
        } catch (IllegalArgumentException e) {
            return no(e.getMessage());
        } catch (RuntimeException e) {
            return no("the command failed: " + Trouble.describe(e));
        }
    }

    private Result device(String uid, String text) {
        Map.Entry<DeviceKind, Object> found = scan.find(uid);
        Device device = scan.device(uid);
        if (found == null || device == null) {
            return no("there is no device " + uid + " in flat " + topics.flatId());
        }
        DeviceKind kind = found.getKey();
        if (!kind.actuator()) {
            return no(device.name() + " is a " + kind.type + " sensor: only lights, heaters and speakers take "
                    + "commands");
        }
        String parameter;
        String value;
        String plain = text.strip();
        if (plain.equalsIgnoreCase("ON") || plain.equalsIgnoreCase("OFF")) {
            parameter = kind.command;
            value = kind.onOff(plain.equalsIgnoreCase("ON"));
        } else {
            Map<String, Object> o = object(text);
            Object p = o.get("parameter");
            if (!(p instanceof String ps) || ps.isBlank()) {
                return no("give the parameter to set, e.g. {\"parameter\":\"" + kind.command + "\",\"value\":"
                        + (kind == DeviceKind.LIGHT ? "true" : "50") + "}");
            }
            parameter = ps;
            if (!o.containsKey("value") || o.get("value") == null) {
                return no("give a value for " + parameter);
            }
            value = valueText(o.get("value"));
        }
        if (!parameter.equals(kind.command)) {
            return no("only '" + kind.command + "' can be set over MQTT on " + device.name() + " (a " + kind.type
                    + "); other parameters are changed in the shell or the web console");
        }
        try {
            device.setParameter(parameter, value);
        } catch (IllegalArgumentException e) {
            return no("cannot set " + parameter + " on " + uid + ": " + e.getMessage());
        }
        return new Result(true, device.name() + ": " + parameter + "=" + value
                + " requested; the state changes when the node confirms it");
    }

    /**
     * @return the JSON object a payload holds
     * @throws IllegalArgumentException what is wrong and where, e.g. "the payload is not valid JSON: ',' or '}'
     *         expected at character 14" (strict JSON, at most {@link #MAX_PAYLOAD} characters and 16 levels)
     */
    static Map<String, Object> object(String text) {
        try {
            return JsonReader.object(text, MAX_PAYLOAD);
        } catch (JsonException e) {
            throw new IllegalArgumentException("the payload is " + e.getMessage(), e);
        }
    }

    private Result ack(String id, String text) {
        Map<String, Object> o = object(text);
        Object by = o.get("by");
        if (!(by instanceof String who) || who.isBlank()) {
            return no("say who takes care of alert " + id + ", e.g. {\"by\":\"Anna (care centre)\"}");
        }
        if (who.length() > 200) {
            return no("the name in 'by' is longer than 200 characters");
        }
        AlertService service = alerts.get();
        if (service == null) {
            return no("no alert service runs in flat " + topics.flatId() + ": nothing to acknowledge");
        }
        try {
            service.acknowledge(id, who.strip());
        } catch (IllegalArgumentException | IllegalStateException e) {
            return no(e.getMessage());
        }
        return new Result(true, "alert " + id + " acknowledged by " + who.strip());
    }

    private static String valueText(Object v) {
        if (v instanceof Double d && d == Math.rint(d) && !d.isInfinite()) {
            return Long.toString(d.longValue());
        }
        if (v instanceof Map || v instanceof java.util.List) {
            throw new IllegalArgumentException("the value must be true/false, a number or a text");
        }
        return v.toString();
    }

    private static String utf8(byte[] payload) {
        try {
            return StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(payload)).toString();
        } catch (CharacterCodingException e) {
            throw new IllegalArgumentException("the payload is not UTF-8 text");
        }
    }

    private static Result no(String reason) {
        return new Result(false, reason);
    }
}

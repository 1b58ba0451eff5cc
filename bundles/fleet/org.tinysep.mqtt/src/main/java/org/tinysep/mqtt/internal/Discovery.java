package org.tinysep.mqtt.internal;

import static org.tinysep.json.JsonWriter.object;
import static org.tinysep.json.JsonWriter.writePlain;

import java.util.List;
import java.util.Map;
import org.tinysep.api.alert.AlertKind;

/**
 * Home Assistant MQTT discovery (https://www.home-assistant.io/integrations/mqtt/#mqtt-discovery): one retained
 * config per entity under {@code <discoveryPrefix>/<component>/tinysep_F_<object>/config}, each with a unique id,
 * the flat's and the device's availability topics (both must say online), and a device block (one HA device per
 * TinySEP device, linked to one HA device for the flat).
 */
final class Discovery {

    private final Topics topics;

    Discovery(Topics topics) {
        this.topics = topics;
    }

    /** The HA device of the whole flat: occupancy and alert sensors. */
    private Map<String, Object> flatDevice() {
        return object("identifiers", List.of(topics.uniqueId("flat")), "name", "TinySEP " + topics.flatId(),
                "manufacturer", "TinySEP", "model", "TinySEP platform");
    }

    Message device(String uid, DeviceKind kind, String name, String room) {
        Map<String, Object> c = object("name", null, "unique_id", topics.uniqueId(uid),
                "object_id", topics.uniqueId(uid), "state_topic", topics.deviceState(uid));
        switch (kind.component) {
            case "binary_sensor" -> {
                c.put("value_template", "{{ 'ON' if value_json.value else 'OFF' }}");
                c.put("device_class", kind.deviceClass);
            }
            case "sensor" -> {
                c.put("value_template", "{{ value_json.value }}");
                if (kind.deviceClass != null) {
                    c.put("device_class", kind.deviceClass);
                }
                c.put("unit_of_measurement", kind == DeviceKind.TEMPERATURE ? "°C" : "%");
                c.put("state_class", "measurement");
            }
            case "light" -> {
                c.put("schema", "basic");
                c.put("state_value_template", "{{ 'ON' if value_json.value else 'OFF' }}");
                c.put("command_topic", topics.deviceCommand(uid));
                c.put("payload_on", "ON");
                c.put("payload_off", "OFF");
            }
            default -> { // switch
                c.put("value_template", "{{ 'ON' if value_json.value else 'OFF' }}");
                c.put("command_topic", topics.deviceCommand(uid));
                c.put("payload_on", "ON");
                c.put("payload_off", "OFF");
                c.put("state_on", "ON");
                c.put("state_off", "OFF");
            }
        }
        c.put("availability", List.of(object("topic", topics.status()),
                object("topic", topics.deviceAvailability(uid))));
        c.put("availability_mode", "all");
        c.put("qos", 1);
        Map<String, Object> device = object("identifiers", List.of(topics.uniqueId(uid)), "name", name,
                "manufacturer", "TinySEP", "model", kind.type, "via_device", topics.uniqueId("flat"));
        if (!room.isEmpty()) { // Home Assistant refuses the whole config when suggested_area is null
            device.put("suggested_area", room);
        }
        c.put("device", device);
        return Message.state(topics.discoveryConfig(kind.component, uid), writePlain(c));
    }

    /** A low-battery problem sensor for a node whose protocol reports its battery. */
    Message battery(String uid) {
        Map<String, Object> c = object("name", "Battery", "unique_id", topics.uniqueId(uid + "_battery"),
                "object_id", topics.uniqueId(uid + "_battery"), "state_topic", topics.deviceHealth(uid),
                "value_template", "{{ 'ON' if value_json.batteryLow else 'OFF' }}", "device_class", "battery",
                "availability_topic", topics.status(), "qos", 1,
                "device", object("identifiers", List.of(topics.uniqueId(uid))));
        return Message.state(topics.discoveryConfig("binary_sensor", uid + "_battery"), writePlain(c));
    }

    Message occupancy() {
        Map<String, Object> c = object("name", "Occupancy", "unique_id", topics.uniqueId("occupancy"),
                "object_id", topics.uniqueId("occupancy"), "state_topic", topics.occupancy(),
                "value_template", "{{ 'ON' if value_json.state == 'OCCUPIED' else 'OFF' }}",
                "device_class", "occupancy", "availability_topic", topics.status(), "qos", 1,
                "device", flatDevice());
        return Message.state(topics.discoveryConfig("binary_sensor", "occupancy"), writePlain(c));
    }

    Message alertKind(AlertKind kind) {
        String object = "alert_" + kind.name().toLowerCase();
        Map<String, Object> c = object("name", "Alert " + kind.words(),
                "unique_id", topics.uniqueId(object), "object_id", topics.uniqueId(object),
                "state_topic", topics.alertKind(kind.name()), "value_template", "{{ value_json.state }}",
                "json_attributes_topic", topics.alertKind(kind.name()),
                "device_class", "problem", "availability_topic", topics.status(), "qos", 1,
                "device", flatDevice());
        return Message.state(topics.discoveryConfig("binary_sensor", object), writePlain(c));
    }
}

package org.tinysep.mqtt.internal;

import org.tinysep.json.JsonWriter;

/**
 * Test-only window on the bridge's own topic names (package-private in org.tinysep.mqtt) and its JSON writing, so
 * that the board's load test publishes exactly what the bridge publishes instead of a second copy of the topic
 * format. Lives in the board's test sources under the bridge's package name (plain class path in tests, no OSGi).
 */
public final class BridgeWire {

    private final Topics topics;

    public BridgeWire(String prefix, String flatId) {
        this.topics = new Topics(prefix, flatId, "");
    }

    public String status() {
        return topics.status();
    }

    public String platform() {
        return topics.platform();
    }

    public String summary() {
        return topics.summary();
    }

    public String occupancy() {
        return topics.occupancy();
    }

    public String deviceState(String uid) {
        return topics.deviceState(uid);
    }

    public String deviceHealth(String uid) {
        return topics.deviceHealth(uid);
    }

    public String alert(String id) {
        return topics.alert(id);
    }

    public String alertAcks() {
        return topics.alertAcks();
    }

    /** @return the bridge's JSON of key/value pairs (values: strings, numbers, booleans, Instants, null) */
    public static String json(Object... keyValues) {
        return JsonWriter.writePlain(JsonWriter.object(keyValues));
    }
}

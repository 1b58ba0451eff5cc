package org.tinysep.mqtt.internal;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * One message to publish.
 *
 * @param topic    where
 * @param payload  what (empty: with {@code retained}, removes the broker's retained message)
 * @param retained whether the broker keeps it for later subscribers
 * @param key      the outbox key (the per-flat {@code seq}) of an alert message kept on disk, else -1
 * @param alertId  the alert it is about, else empty
 */
record Message(String topic, byte[] payload, boolean retained, long key, String alertId) {

    static final int QOS = 1;

    static Message state(String topic, String payload) {
        return new Message(topic, payload.getBytes(StandardCharsets.UTF_8), true, -1, "");
    }

    static Message transientMessage(String topic, String payload) {
        return new Message(topic, payload.getBytes(StandardCharsets.UTF_8), false, -1, "");
    }

    boolean spooled() {
        return key >= 0;
    }

    String text() {
        return new String(payload, StandardCharsets.UTF_8);
    }

    boolean samePayload(Message other) {
        return other != null && retained == other.retained && Arrays.equals(payload, other.payload);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Message m && topic.equals(m.topic) && Arrays.equals(payload, m.payload)
                && retained == m.retained && key == m.key && alertId.equals(m.alertId);
    }

    @Override
    public int hashCode() {
        return topic.hashCode() * 31 + Arrays.hashCode(payload);
    }

    @Override
    public String toString() {
        return topic + (key >= 0 ? " #" + key : "") + " (" + payload.length + " bytes)";
    }
}

package org.tinysep.mqtt.board.loadtest;

import java.time.Instant;
import org.tinysep.mqtt.internal.BridgeWire;

/**
 * The messages a TinySEP flat's MQTT bridge publishes (topic contract v1, docs/mqtt.md), as the simulated flats send
 * them: the topic names and the JSON writer are the bridge's own ({@link BridgeWire} opens org.tinysep.mqtt's
 * Topics and Json to the tests), the payloads carry the fields the bridge's FlatState, DeviceScan and Alerts write.
 */
final class Wire {

    private final BridgeWire topics;
    private final String flat;

    Wire(String prefix, String flat) {
        this.topics = new BridgeWire(prefix, flat);
        this.flat = flat;
    }

    String status() {
        return topics.status();
    }

    String platform() {
        return topics.platform();
    }

    String occupancy() {
        return topics.occupancy();
    }

    String summary() {
        return topics.summary();
    }

    String deviceState(String uid) {
        return topics.deviceState(uid);
    }

    String deviceHealth(String uid) {
        return topics.deviceHealth(uid);
    }

    String alert(long id) {
        return topics.alert(Long.toString(id));
    }

    String acks() {
        return topics.alertAcks();
    }

    String platformJson(Instant started, Instant now, int heartbeatSeconds) {
        return BridgeWire.json("flat", flat, "version", "0.1.0-SNAPSHOT", "startedAt", started, "heartbeatAt", now,
                "heartbeatSeconds", heartbeatSeconds, "explanation", "TinySEP of flat " + flat
                + " is running; it says so every " + heartbeatSeconds + " s");
    }

    String summaryJson(Instant now) {
        return BridgeWire.json("at", now, "text", "TinySEP is running: 23 devices, no open alert", "openAlerts", 0);
    }

    String occupancyJson(boolean occupied, Instant now) {
        return BridgeWire.json("state", occupied ? "OCCUPIED" : "UNOCCUPIED", "since", now, "explanation",
                (occupied ? "someone is at home" : "nobody is at home") + " (since " + now + ")");
    }

    String deviceStateJson(String uid, boolean motion, Instant now) {
        return BridgeWire.json("uid", uid, "name", "Movement sensor " + uid, "room", "Kitchen", "type", "movement",
                "value", motion, "since", now, "explanation", "Kitchen: " + (motion ? "movement" : "no movement"));
    }

    String healthJson(boolean online, int millivolts, Instant now) {
        return BridgeWire.json("status", online ? "ONLINE" : "OFFLINE", "battery", null, "batteryMillivolts", millivolts,
                "batteryLow", millivolts < 2200, "lastReport", now, "linkQuality", 90, "explanation",
                online ? "Kitchen: reporting normally" : "Kitchen: silent for 30 report intervals");
    }

    String alertJson(long id, String state, Instant raisedAt, String by, Instant ackAt, long seq) {
        boolean acked = state.equals("ACKNOWLEDGED");
        boolean cleared = state.equals("CLEARED");
        return BridgeWire.json("id", Long.toString(id), "flat", flat, "kind", "INACTIVITY", "state", state,
                "raisedAt", raisedAt, "room", "Bedroom", "title", "TinySEP: no activity in Bedroom",
                "text", "No movement for 2 h while the flat is occupied", "acknowledgedBy", acked ? by : null,
                "acknowledgedAt", acked ? ackAt : null, "clearedAt", cleared ? ackAt : null,
                "clearedWhy", cleared ? "movement in the kitchen" : null, "explanation", state.toLowerCase(), "seq", seq);
    }
}

package org.tinysep.mqtt.board.loadtest;

import java.time.Instant;

/**
 * The messages a TinySEP flat's MQTT bridge publishes (topic contract v1, docs/mqtt.md), as the simulated flats send
 * them: the same topics, retain flags and JSON fields as the bridge (org.tinysep.mqtt's Topics, FlatState, Alerts).
 */
final class Wire {

    private final String base;
    private final String flat;

    Wire(String prefix, String flat) {
        this.base = prefix + "/" + flat;
        this.flat = flat;
    }

    String status() {
        return base + "/status";
    }

    String platform() {
        return base + "/platform";
    }

    String occupancy() {
        return base + "/occupancy";
    }

    String summary() {
        return base + "/summary";
    }

    String deviceState(String uid) {
        return base + "/device/" + uid + "/state";
    }

    String deviceHealth(String uid) {
        return base + "/device/" + uid + "/health";
    }

    String alert(long id) {
        return base + "/alert/" + id;
    }

    String acks() {
        return base + "/command/alert/+/ack";
    }

    String platformJson(Instant started, Instant now, int heartbeatSeconds) {
        return "{\"flat\":\"" + flat + "\",\"version\":\"0.1.0-SNAPSHOT\",\"startedAt\":\"" + started + "\",\"heartbeatAt\":\""
                + now + "\",\"heartbeatSeconds\":" + heartbeatSeconds + ",\"explanation\":\"platform running, heartbeat every "
                + heartbeatSeconds + " s\"}";
    }

    String summaryJson(Instant now) {
        return "{\"at\":\"" + now + "\",\"text\":\"TinySEP is running: 23 devices, no open alert\"}";
    }

    String occupancyJson(boolean occupied, Instant now) {
        return "{\"state\":\"" + (occupied ? "OCCUPIED" : "UNOCCUPIED") + "\",\"since\":\"" + now + "\",\"explanation\":\""
                + (occupied ? "movement in the kitchen after the front door closed" : "the front door closed and no movement followed")
                + "\"}";
    }

    String deviceStateJson(String uid, boolean motion, Instant now) {
        return "{\"uid\":\"" + uid + "\",\"name\":\"Movement sensor " + uid + "\",\"room\":\"Kitchen\",\"type\":\"movement\","
                + "\"value\":" + motion + ",\"since\":\"" + now + "\",\"explanation\":\"" + (motion ? "movement detected" : "no movement")
                + "\"}";
    }

    String healthJson(boolean online, int battery, Instant now) {
        return "{\"status\":\"" + (online ? "ONLINE" : "OFFLINE") + "\",\"battery\":" + battery + ",\"lastReport\":\"" + now
                + "\",\"explanation\":\"" + (online ? "reporting normally" : "silent for 30 report intervals") + "\"}";
    }

    String alertJson(long id, String state, Instant raisedAt, String by, Instant ackAt, long seq) {
        boolean acked = state.equals("ACKNOWLEDGED");
        return "{\"id\":\"" + id + "\",\"flat\":\"" + flat + "\",\"kind\":\"INACTIVITY\",\"state\":\"" + state + "\",\"raisedAt\":\""
                + raisedAt + "\",\"room\":\"Bedroom\",\"title\":\"No activity in the flat\",\"text\":\"No movement for 2 h"
                + " while the flat is occupied\",\"acknowledgedBy\":" + (acked ? "\"" + by + "\"" : "null") + ",\"acknowledgedAt\":"
                + (acked ? "\"" + ackAt + "\"" : "null") + ",\"explanation\":\"" + state.toLowerCase() + "\",\"seq\":" + seq + "}";
    }
}

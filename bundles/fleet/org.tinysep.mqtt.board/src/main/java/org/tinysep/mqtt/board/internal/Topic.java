package org.tinysep.mqtt.board.internal;

import java.util.Optional;

/**
 * One topic the board reads, split per the contract ({@code P/F/status}, {@code P/F/platform},
 * {@code P/F/summary}, {@code P/F/occupancy}, {@code P/F/alert/<id>}, {@code P/F/device/<uid>/health}).
 *
 * @param flat the flat id (the topic's second level)
 * @param kind what the message is
 * @param id the alert id or device uid, empty for the other kinds
 */
record Topic(String flat, Kind kind, String id) {

    enum Kind { STATUS, PLATFORM, SUMMARY, OCCUPANCY, ALERT, HEALTH }

    /** @return the parsed topic, empty when it is not one the board reads (under this prefix) */
    static Optional<Topic> parse(String prefix, String topic) {
        if (topic == null || !topic.startsWith(prefix + "/")) {
            return Optional.empty();
        }
        String[] l = topic.substring(prefix.length() + 1).split("/", -1);
        if (l.length < 2 || l[0].isEmpty()) {
            return Optional.empty();
        }
        String flat = l[0];
        if (l.length == 2) {
            return switch (l[1]) {
                case "status" -> Optional.of(new Topic(flat, Kind.STATUS, ""));
                case "platform" -> Optional.of(new Topic(flat, Kind.PLATFORM, ""));
                case "summary" -> Optional.of(new Topic(flat, Kind.SUMMARY, ""));
                case "occupancy" -> Optional.of(new Topic(flat, Kind.OCCUPANCY, ""));
                default -> Optional.empty();
            };
        }
        if (l.length == 3 && l[1].equals("alert") && !l[2].isEmpty()) {
            return Optional.of(new Topic(flat, Kind.ALERT, l[2]));
        }
        if (l.length == 4 && l[1].equals("device") && l[3].equals("health") && !l[2].isEmpty()) {
            return Optional.of(new Topic(flat, Kind.HEALTH, l[2]));
        }
        return Optional.empty();
    }

    /** @return the topic filters the board subscribes to */
    static String[] filters(String prefix) {
        return new String[] {prefix + "/+/status", prefix + "/+/platform", prefix + "/+/summary",
            prefix + "/+/occupancy", prefix + "/+/alert/+", prefix + "/+/device/+/health"};
    }

    /** @return where an acknowledgement of the flat's alert is published */
    static String ack(String prefix, String flat, String alertId) {
        return prefix + "/" + flat + "/command/alert/" + alertId + "/ack";
    }
}

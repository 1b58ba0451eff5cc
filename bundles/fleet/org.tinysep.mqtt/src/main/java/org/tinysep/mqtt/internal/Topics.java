package org.tinysep.mqtt.internal;

/** The topic names of the contract (docs/mqtt.md): {@code P/F/...} and the Home Assistant discovery topics. */
final class Topics {

    private final String base;
    private final String discoveryPrefix;
    private final String flatId;

    Topics(String prefix, String flatId, String discoveryPrefix) {
        this.base = prefix + "/" + flatId;
        this.flatId = flatId;
        this.discoveryPrefix = discoveryPrefix;
    }

    /** Any of {@code + # /}, control characters and spaces become {@code _}. */
    static String level(String s) {
        StringBuilder b = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            b.append(c == '+' || c == '#' || c == '/' || Character.isISOControl(c) || Character.isWhitespace(c)
                    ? '_' : c);
        }
        return b.length() == 0 ? "_" : b.toString();
    }

    String flatId() {
        return flatId;
    }

    /** @return {@code P/F/<levels>}: the one place the flat's topics are built */
    private String at(String... levels) {
        return base + "/" + String.join("/", levels);
    }

    /** @return {@code P/F/device/<uid>/<leaf>} */
    private String device(String uid, String leaf) {
        return at("device", level(uid), leaf);
    }

    String status() {
        return at("status");
    }

    String platform() {
        return at("platform");
    }

    String summary() {
        return at("summary");
    }

    /** Additive to the contract (v1): the drivers list, retained. */
    String drivers() {
        return at("drivers");
    }

    String occupancy() {
        return at("occupancy");
    }

    String deviceState(String uid) {
        return device(uid, "state");
    }

    String deviceAvailability(String uid) {
        return device(uid, "availability");
    }

    String deviceHealth(String uid) {
        return device(uid, "health");
    }

    String alert(String id) {
        return at("alert", level(id));
    }

    /** Additive to the contract (v1): one retained ON/OFF per alert kind, for Home Assistant's problem sensors. */
    String alertKind(String kind) {
        return at("alertkind", level(kind));
    }

    String deviceCommand(String uid) {
        return at("command", "device", level(uid));
    }

    String deviceCommands() {
        return at("command", "device", "+");
    }

    String alertAcks() {
        return at("command", "alert", "+", "ack");
    }

    String commandPrefix() {
        return at("command", "");
    }

    String commandResult() {
        return at("command", "result");
    }

    boolean discovery() {
        return !discoveryPrefix.isEmpty();
    }

    /** @return {@code homeassistant/<component>/tinysep_F_<object>/config} */
    String discoveryConfig(String component, String object) {
        return discoveryPrefix + "/" + component + "/" + uniqueId(object) + "/config";
    }

    String uniqueId(String object) {
        return "tinysep_" + flatId + "_" + level(object);
    }
}

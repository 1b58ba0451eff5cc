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

    String status() {
        return base + "/status";
    }

    String platform() {
        return base + "/platform";
    }

    String summary() {
        return base + "/summary";
    }

    String occupancy() {
        return base + "/occupancy";
    }

    String deviceState(String uid) {
        return base + "/device/" + level(uid) + "/state";
    }

    String deviceAvailability(String uid) {
        return base + "/device/" + level(uid) + "/availability";
    }

    String deviceHealth(String uid) {
        return base + "/device/" + level(uid) + "/health";
    }

    String alert(String id) {
        return base + "/alert/" + level(id);
    }

    /** Additive to the contract (v1): one retained ON/OFF per alert kind, for Home Assistant's problem sensors. */
    String alertKind(String kind) {
        return base + "/alertkind/" + level(kind);
    }

    String deviceCommand(String uid) {
        return base + "/command/device/" + level(uid);
    }

    String deviceCommands() {
        return base + "/command/device/+";
    }

    String alertAcks() {
        return base + "/command/alert/+/ack";
    }

    String commandPrefix() {
        return base + "/command/";
    }

    String commandResult() {
        return base + "/command/result";
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

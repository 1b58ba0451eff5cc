package org.tinysep.mqtt.internal;

import java.net.URI;
import java.nio.file.Path;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * The bridge's configuration, checked: a refused configuration says why in plain words.
 *
 * @param brokerUrl empty when the bridge is idle
 */
record Settings(String brokerUrl, String flatId, String username, Path passwordFile, Path trustStore,
        String trustStorePassword, Path keyStore, Path keyStorePasswordFile, String topicPrefix,
        String discoveryPrefix, int heartbeatSeconds, int sessionExpirySeconds, Path queueDir, int pollSeconds,
        boolean allowAnonymous, Path keyFile, CommandPolicy ackCommands, CommandPolicy actuatorCommands,
        int commandMaxAgeSeconds) {

    private static final Pattern FLAT = Pattern.compile("[A-Za-z0-9_.-]{1,64}");
    private static final Pattern PREFIX = Pattern.compile("[A-Za-z0-9_.-]+(/[A-Za-z0-9_.-]+)*");

    boolean configured() {
        return !brokerUrl.isEmpty();
    }

    boolean tls() {
        return brokerUrl.startsWith("ssl://");
    }

    /**
     * @return true when the bridge would log in to the broker without credentials: no user name (with its
     *         {@code passwordFile}) and no client certificate ({@code keyStore}); such a broker lets anyone in
     */
    boolean anonymous() {
        return username.isEmpty() && keyStore == null;
    }

    /** @return the settings for one line of the log and the device's parameters: no secrets */
    String redacted() {
        return brokerUrl + " as " + flatId + (username.isEmpty() ? " (anonymous)" : " (user " + username + ")")
                + ", topics " + topicPrefix + "/" + flatId + "/…";
    }

    /**
     * @param var  the state folder ({@code tinysep.var}), for the default password file and outbox
     * @throws IllegalArgumentException what is wrong, in plain words
     */
    static Settings parse(Map<String, ?> p, Path var) {
        String url = text(p, "brokerUrl", "");
        if (!url.isEmpty()) {
            URI u;
            try {
                u = URI.create(url);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("brokerUrl '" + url + "' is not a URL like tcp://host:1883");
            }
            if (!"tcp".equals(u.getScheme()) && !"ssl".equals(u.getScheme()) || u.getHost() == null) {
                throw new IllegalArgumentException("brokerUrl '" + url + "' must be tcp://host:port or ssl://host:port");
            }
        }
        String flat = text(p, "flatId", "flat");
        if (!FLAT.matcher(flat).matches()) {
            throw new IllegalArgumentException("flatId '" + flat + "' may only hold letters, digits, '-', '_' and '.'"
                    + " (it is a topic level and the MQTT client id)");
        }
        String prefix = text(p, "topicPrefix", "tinysep");
        if (!PREFIX.matcher(prefix).matches()) {
            throw new IllegalArgumentException("topicPrefix '" + prefix + "' must be topic levels without + # or spaces");
        }
        String discovery = text(p, "discoveryPrefix", "homeassistant");
        if (!discovery.isEmpty() && !PREFIX.matcher(discovery).matches()) {
            throw new IllegalArgumentException("discoveryPrefix '" + discovery
                    + "' must be topic levels without + # or spaces");
        }
        Path mqttVar = var.resolve("mqtt");
        return new Settings(url, flat, text(p, "username", ""),
                path(p, "passwordFile", var.resolve("secrets").resolve("mqtt.password")),
                path(p, "trustStore", null), text(p, "trustStorePassword", "changeit"),
                path(p, "keyStore", null), path(p, "keyStorePasswordFile", null), prefix, discovery,
                number(p, "heartbeatSeconds", 60, 1, 86_400), number(p, "sessionExpirySeconds", 3600, 0, 30 * 86_400),
                path(p, "queueDir", mqttVar), number(p, "pollSeconds", 1, 1, 3600),
                bool(p, "allowAnonymous"), path(p, "keyFile", var.resolve("secrets").resolve("mqtt.key")),
                CommandPolicy.parse("commands.ack", text(p, "commands.ack", "signed")),
                CommandPolicy.parse("commands.actuators", text(p, "commands.actuators", "off")),
                number(p, "commands.maxAgeSeconds", 300, 10, 86_400));
    }

    private static String text(Map<String, ?> p, String key, String dflt) {
        Object v = p.get(key);
        return v == null ? dflt : v.toString().strip();
    }

    private static boolean bool(Map<String, ?> p, String key) {
        String v = text(p, key, "false");
        if (!v.equalsIgnoreCase("true") && !v.equalsIgnoreCase("false")) {
            throw new IllegalArgumentException(key + " must be true or false, was '" + v + "'");
        }
        return Boolean.parseBoolean(v);
    }

    private static Path path(Map<String, ?> p, String key, Path dflt) {
        String v = text(p, key, "");
        return v.isEmpty() ? dflt : Path.of(v);
    }

    private static int number(Map<String, ?> p, String key, int dflt, int min, int max) {
        String v = text(p, key, "");
        if (v.isEmpty()) {
            return dflt;
        }
        try {
            int n = Integer.parseInt(v);
            if (n < min || n > max) {
                throw new IllegalArgumentException(key + " must be " + min + ".." + max + ", was " + n);
            }
            return n;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(key + " must be a whole number, was '" + v + "'");
        }
    }
}

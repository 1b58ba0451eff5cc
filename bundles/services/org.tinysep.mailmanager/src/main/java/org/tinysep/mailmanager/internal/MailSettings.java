package org.tinysep.mailmanager.internal;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;
import org.tinysep.device.support.files.StateFolder;

/**
 * The validated Mail Manager configuration. {@link #toString()} and {@link #redacted()} never show the password.
 *
 * @param host empty when not configured
 */
record MailSettings(String host, int port, Security security, String user, String password, Path passwordFile,
        String from, List<String> recipients, int connectTimeoutSeconds, int retryInitialSeconds, int retryMaxSeconds,
        int giveUpAfterSeconds, Path spoolDir, Path trustedCertificates) {

    static final int DEFAULT_PORT = 587;
    static final int DEFAULT_CONNECT_TIMEOUT = 10;
    static final int DEFAULT_RETRY_INITIAL = 5;
    static final int DEFAULT_RETRY_MAX = 600;
    static final int DEFAULT_GIVE_UP_AFTER = 86400;
    static final String MASK = "***";

    /** Deliberately simple: one @, no blanks or angle brackets, a dot-free host is allowed (e.g. localhost). */
    private static final Pattern ADDRESS = Pattern.compile("[^@\\s<>,;\"]+@[^@\\s<>,;\"]+");

    /** @return whether mail goes to an SMTP server (otherwise it is only written to the log) */
    boolean configured() {
        return !host.isEmpty();
    }

    /**
     * Reads and validates a ConfigAdmin dictionary; absent keys take their defaults.
     *
     * @param tinysepHome the {@code tinysep.home} property, or null
     * @throws IllegalArgumentException naming the key, the bad value (never the password) and what is expected
     */
    static MailSettings parse(Map<String, ?> props, String tinysepHome) {
        return parse(props, null, tinysepHome);
    }

    /**
     * Reads and validates a ConfigAdmin dictionary; absent keys take their defaults.
     *
     * @param tinysepVar  the {@code tinysep.var} property (state folder), or null
     * @param tinysepHome the {@code tinysep.home} property, or null
     * @throws IllegalArgumentException naming the key, the bad value (never the password) and what is expected
     */
    static MailSettings parse(Map<String, ?> props, String tinysepVar, String tinysepHome) {
        String host = text(props, "host");
        int port = number(props, "port", DEFAULT_PORT, 1, 65535);
        Security security = security(text(props, "security"));
        String user = text(props, "user");
        Object pw = props.get("password");
        String password = pw == null ? "" : pw.toString();
        String from = text(props, "from");
        List<String> recipients = recipients(text(props, "recipients"));
        int timeout = number(props, "connectTimeoutSeconds", DEFAULT_CONNECT_TIMEOUT, 1, 3600);
        int initial = number(props, "retryInitialSeconds", DEFAULT_RETRY_INITIAL, 1, 86400);
        int max = number(props, "retryMaxSeconds", DEFAULT_RETRY_MAX, 1, 86400);
        int giveUp = number(props, "giveUpAfterSeconds", DEFAULT_GIVE_UP_AFTER, 1, 30 * 86400);
        if (max < initial) {
            throw new IllegalArgumentException("retryMaxSeconds (" + max + ") must not be below retryInitialSeconds ("
                    + initial + ")");
        }
        if (!host.isEmpty()) {
            if (host.contains(" ") || host.contains("/") || host.contains(":")) {
                throw new IllegalArgumentException("host must be a host name or address without port or scheme, was '"
                        + host + "'");
            }
            if (!ADDRESS.matcher(from).matches()) {
                throw new IllegalArgumentException("from must be one e-mail address like alerts@example.org, was '"
                        + from + "'");
            }
            if (recipients.isEmpty()) {
                throw new IllegalArgumentException("recipients must name at least one address (comma-separated)");
            }
        }
        return new MailSettings(host, port, security, user, password,
                inStateFolder(text(props, "passwordFile"), tinysepVar, tinysepHome, "secrets/smtp.password"), from,
                recipients, timeout, initial, max, giveUp,
                inStateFolder(text(props, "spoolDir"), tinysepVar, tinysepHome, "mail-spool"),
                text(props, "trustedCertificates").isEmpty() ? null
                        : Path.of(text(props, "trustedCertificates")).toAbsolutePath());
    }

    private static String text(Map<String, ?> props, String key) {
        Object v = props.get(key);
        return v == null ? "" : v.toString().strip();
    }

    private static int number(Map<String, ?> props, String key, int dflt, int min, int max) {
        String v = text(props, key);
        if (v.isEmpty()) {
            return dflt;
        }
        int n;
        try {
            n = Integer.parseInt(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(key + " must be a whole number, was '" + v + "'");
        }
        if (n < min || n > max) {
            throw new IllegalArgumentException(key + " must be between " + min + " and " + max + ", was " + n);
        }
        return n;
    }

    private static Security security(String v) {
        if (v.isEmpty()) {
            return Security.STARTTLS;
        }
        try {
            return Security.valueOf(v.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("security must be NONE, STARTTLS or TLS, was '" + v + "'");
        }
    }

    /**
     * @return {@code to}, checked address by address
     * @throws IllegalArgumentException naming the first malformed address
     */
    static List<String> addresses(List<String> to) {
        return to == null ? List.of() : recipients(String.join(",", to));
    }

    private static List<String> recipients(String v) {
        List<String> all = new ArrayList<>();
        for (String part : v.split(",")) {
            String a = part.strip();
            if (a.isEmpty()) {
                continue;
            }
            if (!ADDRESS.matcher(a).matches()) {
                throw new IllegalArgumentException("recipients: '" + a + "' is not an e-mail address");
            }
            all.add(a);
        }
        return List.copyOf(all);
    }

    /** @return the configured path, else {@code <var>/<name>}, {@code <home>/var/<name>}, {@code <name>} */
    private static Path inStateFolder(String v, String tinysepVar, String tinysepHome, String name) {
        return StateFolder.resolve(v, tinysepVar, tinysepHome, name).orElseGet(() -> Path.of(name).toAbsolutePath());
    }

    /** @return a one-line description without the password */
    String redacted() {
        if (!configured()) {
            return "not configured (spool " + spoolDir + ")";
        }
        return security + " " + host + ":" + port + (user.isEmpty() ? "" : " as " + user
                + (password.isEmpty() ? "" : " (password " + MASK + ")")) + ", from " + from + " to "
                + String.join(", ", recipients);
    }

    @Override
    public String toString() {
        return redacted();
    }
}

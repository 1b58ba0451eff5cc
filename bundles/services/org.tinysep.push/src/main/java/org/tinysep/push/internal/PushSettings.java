package org.tinysep.push.internal;

import java.net.URI;
import java.nio.file.Path;

/**
 * The validated configuration of the push channel.
 *
 * @param server  the ntfy server's base URL (https), or null when none is configured
 * @param problem why there is no usable server, in words; empty when {@code server} is set
 */
record PushSettings(URI server, String problem, Path tokenFile, Path trusted, int priority, int timeoutSeconds) {

    static PushSettings parse(PushConfig c, Path defaultTokenFile) {
        Path token = c.tokenFile().isBlank() ? defaultTokenFile : Path.of(c.tokenFile().strip());
        Path trusted = c.trustedCertificates().isBlank() ? null : Path.of(c.trustedCertificates().strip());
        int priority = Math.max(1, Math.min(5, c.priority()));
        int timeout = Math.max(1, c.timeoutSeconds());
        String s = c.server().strip();
        if (s.isEmpty()) {
            return new PushSettings(null, "no push server is configured (key 'server' of org.tinysep.push)", token,
                    trusted, priority, timeout);
        }
        URI u;
        try {
            u = URI.create(s.endsWith("/") ? s : s + "/");
        } catch (IllegalArgumentException e) {
            return new PushSettings(null, "the push server '" + s + "' is not a URL", token, trusted, priority,
                    timeout);
        }
        if (!"https".equalsIgnoreCase(u.getScheme()) || u.getHost() == null) {
            return new PushSettings(null, "the push server '" + s + "' must be an https:// address (alerts are not "
                    + "sent in clear)", token, trusted, priority, timeout);
        }
        return new PushSettings(u, "", token, trusted, priority, timeout);
    }
}

package org.tinysep.web.api.internal;

import java.net.URI;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * Plain HTTP only on this machine: passwords and the session cookie must not cross a network
 * readable. A request that came over plain HTTP to an address other than loopback is refused, unless the
 * configuration allows it explicitly ({@code allowPlainHttpOffLoopback=true}, which is then reported); over TLS the
 * console answers on any address and the cookie carries {@code Secure}.
 */
final class PlainHttpRule {

    private PlainHttpRule() {
    }

    /** @return whether a request that arrived at local address {@code localAddress} over plain HTTP may be served */
    static boolean allowed(boolean secure, String localAddress, boolean override) {
        return secure || override || loopback(localAddress);
    }

    /** The refusal's words: what happened and what to do. */
    static String refusal(String localAddress) {
        return "the web console answers plain HTTP only on this machine (127.0.0.1), not at " + localAddress
                + ": passwords would cross the network readable. Use HTTPS (docs/web-api.md, 'Address'), or, on a"
                + " network you trust, set allowPlainHttpOffLoopback=true in etc/org.tinysep.web.api.cfg";
    }

    /**
     * @param endpoints the HTTP service's endpoints ({@code osgi.http.endpoint}), e.g. {@code http://0.0.0.0:8080/}
     * @return the PROBLEM text (without "Security: ") when one of them is plain HTTP beyond loopback
     */
    static Optional<String> problem(List<String> endpoints, boolean override) {
        List<String> plain = endpoints.stream().filter(e -> e.toLowerCase(Locale.ROOT).startsWith("http:"))
                .filter(e -> !loopback(host(e))).toList();
        if (plain.isEmpty()) {
            return Optional.empty();
        }
        String where = String.join(" ", plain);
        if (override) {
            return Optional.of("the web console is served without TLS at " + where + " (allowPlainHttpOffLoopback=true"
                    + " in org.tinysep.web.api): anyone on that network can read the passwords and the session cookie"
                    + " on their way. Turn on HTTPS (docs/web-api.md, 'Address') and remove that setting");
        }
        return Optional.of("the web console listens without TLS at " + where + "; it refuses plain-HTTP requests"
                + " that do not come to 127.0.0.1, so from the network it cannot be used. Turn on HTTPS"
                + " (docs/web-api.md, 'Address'), or set org.apache.felix.http.host=127.0.0.1 again");
    }

    static boolean loopback(String address) {
        if (address == null) {
            return false;
        }
        String a = address.strip().toLowerCase(Locale.ROOT);
        if (a.startsWith("[") && a.endsWith("]")) {
            a = a.substring(1, a.length() - 1);
        }
        return a.startsWith("127.") || a.equals("::1") || a.equals("0:0:0:0:0:0:0:1") || a.equals("localhost");
    }

    private static String host(String endpoint) {
        try {
            String h = URI.create(endpoint.strip()).getHost();
            return h == null ? "" : h;
        } catch (IllegalArgumentException e) {
            return "";
        }
    }
}

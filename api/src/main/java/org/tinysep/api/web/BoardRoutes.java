package org.tinysep.api.web;

import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The central alert board's routes on the web console's HTTP service ({@code org.tinysep.mqtt.board}), shared with
 * the login filter ({@code org.tinysep.web.api}), which lets a caregiver make one change there: acknowledging an
 * alert.
 */
public final class BoardRoutes {

    /** The board serves everything below this path: its page, its JSON and its acknowledge call. */
    public static final String ROOT = "/board";

    /** The board's servlet pattern ({@code osgi.http.whiteboard.servlet.pattern}). */
    public static final String SERVLET_PATTERN = ROOT + "/*";

    /** {@code POST} here acknowledges an alert of a flat: below {@link #ROOT}, the flat and the alert id. */
    private static final Pattern ACKNOWLEDGE = Pattern.compile("/api/flats/([^/]+)/alerts/([^/]+)/acknowledge");

    /** One acknowledge call: which flat's which alert. */
    public record Acknowledge(String flat, String alertId) {
    }

    private BoardRoutes() {
    }

    /**
     * @param pathInfo the path below {@link #ROOT} (the servlet's {@code getPathInfo()}), may be null
     * @return the flat and alert acknowledged, or empty when the path is no acknowledge call
     */
    public static Optional<Acknowledge> acknowledge(String pathInfo) {
        if (pathInfo == null) {
            return Optional.empty();
        }
        Matcher m = ACKNOWLEDGE.matcher(pathInfo);
        return m.matches() ? Optional.of(new Acknowledge(m.group(1), m.group(2))) : Optional.empty();
    }

    /** @return whether a request URI (from the server's root) is the board's acknowledge call */
    public static boolean isAcknowledge(String requestUri) {
        return requestUri != null && requestUri.startsWith(ROOT + "/")
                && acknowledge(requestUri.substring(ROOT.length())).isPresent();
    }
}

package org.tinysep.launcher;

import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.Collection;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;

/**
 * The banner's line on the web console: its address is said only once the HTTP server has bound,
 * read from the endpoint the HTTP Service Runtime announces ({@code osgi.http.endpoint}), so a port another program
 * holds is never announced as TinySEP's console.
 */
final class WebConsoleLine {

    static final String ENDPOINT = "osgi.http.endpoint";
    static final String HOW_TO_GET_IN = "set a password first: tinysep:web-password installer <password> in the shell,"
            + " or without a shell: ./run.sh --web-password installer (or caregiver)";

    private WebConsoleLine() {
    }

    /**
     * How long the line (and a first use, {@link WebConsole}) waits for the HTTP service to bind (on a loaded machine
     * Jetty takes seconds; a port held by another program never binds).
     */
    static final Duration WAIT = Duration.ofSeconds(10);

    /**
     * @param since {@link System#nanoTime()} of the banner: the line says how soon after it the console was bound
     * @return {@code Web console: <address> (…) - …} once bound, else a warning that it did not start
     */
    static String line(BundleContext context, Duration wait, long since) throws InterruptedException {
        String endpoint = await(context, wait);
        return describe(endpoint, Duration.ofNanos(System.nanoTime() - since));
    }

    /** @return the HTTP service's endpoint once it has bound, {@code null} when it did not within {@code wait} */
    static String await(BundleContext context, Duration wait) throws InterruptedException {
        long end = System.nanoTime() + wait.toNanos();
        String endpoint = endpoint(context);
        while (endpoint == null && System.nanoTime() < end) {
            Thread.sleep(20);
            endpoint = endpoint(context);
        }
        return endpoint;
    }

    /** @return the line for a console that starts on its first use ({@link WebConsole}) */
    static String onFirstUse(InetSocketAddress at) {
        return "Web console: http://" + at.getHostString() + ":" + at.getPort() + "/ (starts on first use, in about"
                + " a second) - " + HOW_TO_GET_IN;
    }

    static String describe(String endpoint, Duration afterBanner) {
        if (endpoint == null) {
            return "WARNING: the web console did not start (its port, org.osgi.service.http.port in "
                    + "etc/org.apache.felix.http.cfg, may be held by another program; the log says why)";
        }
        return String.format(java.util.Locale.ROOT, "Web console: %s (up %.1f s after the banner) - %s", endpoint,
                afterBanner.toMillis() / 1000.0, HOW_TO_GET_IN);
    }

    private static String endpoint(BundleContext context) {
        try {
            ServiceReference<?>[] refs = context.getAllServiceReferences(null, "(" + ENDPOINT + "=*)");
            if (refs == null) {
                return null;
            }
            for (ServiceReference<?> ref : refs) {
                String first = first(ref.getProperty(ENDPOINT));
                if (first != null) {
                    return first;
                }
            }
            return null;
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    static String first(Object value) {
        if (value instanceof String s && !s.isBlank()) {
            return s;
        }
        if (value instanceof String[] a && a.length > 0) {
            return a[0];
        }
        if (value instanceof Collection<?> c && !c.isEmpty()) {
            return String.valueOf(c.iterator().next());
        }
        return null;
    }
}

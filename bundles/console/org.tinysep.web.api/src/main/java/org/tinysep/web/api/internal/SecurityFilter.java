package org.tinysep.web.api.internal;

import jakarta.servlet.Filter;
import jakarta.servlet.FilterChain;
import jakarta.servlet.ServletException;
import jakarta.servlet.ServletRequest;
import jakarta.servlet.ServletResponse;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.Map;
import java.util.Optional;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.tinysep.api.web.BoardRoutes;
import org.tinysep.api.web.WebConsole;
import org.tinysep.web.api.internal.Sessions.Session;

/**
 * Guards every page and API call of the HTTP service's default context: without a session, API calls get 401 and
 * pages a redirect to the login page; a state-changing call (anything but GET/HEAD) needs the session's CSRF token
 * in header {@value #CSRF_HEADER} and, when the browser sends an Origin, the same origin, else 403; the caregiver
 * may only read (403), except acknowledging an alert (the console's and the central board's acknowledge calls).
 * Every answer gets the security headers (CSP without inline script, no framing, no sniffing). Plain HTTP is
 * served only on loopback unless configured otherwise ({@link PlainHttpRule}).
 */
@Component(service = Filter.class, property = {
    "osgi.http.whiteboard.filter.pattern=/*",
    "osgi.http.whiteboard.filter.name=tinysep-web-security"
})
public final class SecurityFilter implements Filter {

    /** Header carrying the CSRF token on state-changing calls. */
    public static final String CSRF_HEADER = "X-CSRF-Token";
    static final String CSP = "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
            + "connect-src 'self'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'";

    private static final java.util.regex.Pattern ACKNOWLEDGE = java.util.regex.Pattern.compile("/api/alerts/[^/]+/acknowledge");

    private final WebSecurity security;

    @Activate
    public SecurityFilter(@Reference WebSecurity security) {
        this.security = security;
    }

    @Override
    public void doFilter(ServletRequest request, ServletResponse response, FilterChain chain)
            throws IOException, ServletException {
        HttpServletRequest req = (HttpServletRequest) request;
        HttpServletResponse resp = (HttpServletResponse) response;
        headers(resp);
        if (!PlainHttpRule.allowed(req.isSecure(), req.getLocalAddr(), security.plainHttpOffLoopback())) {
            deny(req, resp, 403, PlainHttpRule.refusal(req.getLocalAddr()));
            return;
        }
        String path = req.getRequestURI() == null ? "/" : req.getRequestURI();
        String method = req.getMethod();
        boolean api = path.startsWith("/api/") || path.equals("/api");
        boolean reads = method.equals("GET") || method.equals("HEAD");
        if (WebConsole.PUBLIC_PAGES.contains(path) && reads) {
            chain.doFilter(req, resp);
            return;
        }
        if (path.equals("/api/session") && method.equals("POST")) { // logging in: no session yet
            if (!sameOrigin(req)) {
                deny(req, resp, 403, "cross-site request refused");
                return;
            }
            chain.doFilter(req, resp);
            return;
        }
        Optional<Session> session = security.sessions().find(SessionApi.token(req));
        if (session.isEmpty()) {
            if (api) {
                deny(req, resp, 401, "log in first");
            } else {
                resp.setStatus(302);
                resp.setHeader("Location", WebConsole.LOGIN_PAGE);
            }
            return;
        }
        Session s = session.get();
        if (!reads) {
            if (!sameOrigin(req) || !csrfMatches(req.getHeader(CSRF_HEADER), s.csrf())) {
                deny(req, resp, 403, "missing or wrong CSRF token (header " + CSRF_HEADER + ")");
                return;
            }
            boolean logout = path.equals("/api/session") && method.equals("DELETE");
            if (s.role() != Role.INSTALLER && !logout && !caregiverMay(method, path)) {
                deny(req, resp, 403, "the " + s.role().id() + " may look but not change anything: log in as installer");
                return;
            }
        }
        req.setAttribute(SessionApi.SESSION_ATTRIBUTE, s);
        req.setAttribute(WebConsole.ROLE_ATTRIBUTE, s.role().id());
        chain.doFilter(req, resp);
    }

    /**
     * The one change a caregiver may make: acknowledging an alert (the flat's own, or one on the central board, whose
     * route the board's bundle shares through {@link BoardRoutes}).
     */
    static boolean caregiverMay(String method, String path) {
        return method.equals("POST") && (ACKNOWLEDGE.matcher(path).matches() || BoardRoutes.isAcknowledge(path));
    }

    static void headers(HttpServletResponse resp) {
        resp.setHeader("Content-Security-Policy", CSP);
        resp.setHeader("X-Content-Type-Options", "nosniff");
        resp.setHeader("X-Frame-Options", "DENY");
        resp.setHeader("Referrer-Policy", "no-referrer");
    }

    /** @return false when the browser says the request comes from another site */
    static boolean sameOrigin(HttpServletRequest req) {
        String origin = req.getHeader("Origin");
        if (origin == null || origin.isEmpty()) {
            return true; // not a browser, or a same-origin GET; SameSite=Strict keeps the cookie off cross-site requests
        }
        String host = req.getHeader("Host");
        return host != null && (origin.equals("http://" + host) || origin.equals("https://" + host));
    }

    private static boolean csrfMatches(String given, String expected) {
        return given != null && MessageDigest.isEqual(given.getBytes(StandardCharsets.UTF_8),
                expected.getBytes(StandardCharsets.UTF_8));
    }

    private static void deny(HttpServletRequest req, HttpServletResponse resp, int status, String message)
            throws IOException {
        drain(req);
        ApiServlet.send(resp, status, Map.of("error", message));
    }

    /**
     * Reads and drops a refused request's body (up to 16 MiB): a client still writing it, e.g. a jar upload, then
     * reads the refusal instead of meeting a closed connection ("Broken pipe", seen once in a CI-like run).
     */
    private static void drain(HttpServletRequest req) {
        long length = req.getContentLengthLong();
        if (length <= 0 || length > (16L << 20)) {
            return;
        }
        try {
            req.getInputStream().transferTo(java.io.OutputStream.nullOutputStream());
        } catch (IOException | RuntimeException e) { // the client gave up: nothing to answer
        }
    }
}

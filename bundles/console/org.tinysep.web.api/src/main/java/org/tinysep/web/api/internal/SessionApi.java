package org.tinysep.web.api.internal;

import jakarta.servlet.http.Cookie;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.web.api.internal.Sessions.Session;

/**
 * {@code /api/session}: POST logs in ({@code {"user": "installer"|"caregiver", "password": "..."}}; rate-limited),
 * GET tells who is logged in and the CSRF token, DELETE logs out. The session cookie is HttpOnly,
 * SameSite=Strict, and Secure when the request came over TLS.
 */
public final class SessionApi {

    /** Name of the session cookie. */
    public static final String COOKIE = "TINYSEP_SESSION";
    /** Request attribute the filter sets to the logged-in {@link Session}. */
    public static final String SESSION_ATTRIBUTE = "org.tinysep.web.session";

    private static final Logger LOG = LoggerFactory.getLogger(SessionApi.class);

    private final WebSecurity security;

    public SessionApi(WebSecurity security) {
        this.security = security;
    }

    public Map<String, Object> current(HttpServletRequest req) {
        Session s = (Session) req.getAttribute(SESSION_ATTRIBUTE);
        if (s == null) {
            throw new ApiException(401, "not logged in");
        }
        return json(s);
    }

    public Map<String, Object> login(HttpServletRequest req, HttpServletResponse resp, Map<String, String> body) {
        String client = req.getRemoteAddr();
        Optional<Role> role = Role.parse(body.get("user"));
        String account = role.map(Role::id).orElse("(unknown user)");
        LoginLimiter.Wait wait = security.limiter().waitFor(client, account);
        if (wait.refused()) {
            long seconds = Math.max(1, wait.duration().toSeconds() + 1);
            resp.setHeader("Retry-After", Long.toString(seconds));
            throw new ApiException(429, "too many failed logins (" + wait.reason() + "): try again in " + seconds + " s");
        }
        if (!security.passwords().anySet()) {
            throw new ApiException(403, "no password is set yet: set one in the TinySEP shell with "
                    + "tinysep:web-password installer <password>");
        }
        String password = body.getOrDefault("password", "");
        if (role.isEmpty() || !security.passwords().verify(role.get(), password)) {
            security.limiter().failed(client, account).ifPresent(security::problem);
            LOG.info("Failed web console login as '{}' from {}", Strings.shorten(body.getOrDefault("user", ""), 40), client);
            throw new ApiException(401, "wrong user name or password");
        }
        security.limiter().succeeded(client, account);
        Session s = security.sessions().open(role.get());
        resp.addHeader("Set-Cookie", COOKIE + "=" + s.token() + "; Path=/; HttpOnly; SameSite=Strict"
                + (req.isSecure() ? "; Secure" : ""));
        LOG.info("Web console login as {} from {}", role.get().id(), client);
        return json(s);
    }

    public Map<String, Object> logout(HttpServletRequest req, HttpServletResponse resp) {
        Session s = (Session) req.getAttribute(SESSION_ATTRIBUTE);
        if (s != null) {
            security.sessions().close(s.token());
        }
        resp.addHeader("Set-Cookie", COOKIE + "=; Path=/; Max-Age=0; HttpOnly; SameSite=Strict"
                + (req.isSecure() ? "; Secure" : ""));
        return Map.of("loggedOut", true);
    }

    /** @return the session token the request's cookie carries, or null */
    static String token(HttpServletRequest req) {
        Cookie[] cookies = req.getCookies();
        if (cookies == null) {
            return null;
        }
        for (Cookie c : cookies) {
            if (COOKIE.equals(c.getName())) {
                return c.getValue();
            }
        }
        return null;
    }

    private static Map<String, Object> json(Session s) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("role", s.role().id());
        m.put("csrf", s.csrf());
        return m;
    }
}

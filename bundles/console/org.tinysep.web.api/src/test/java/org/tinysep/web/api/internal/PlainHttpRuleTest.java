package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jakarta.servlet.ServletOutputStream;
import jakarta.servlet.WriteListener;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;
import java.io.ByteArrayOutputStream;
import java.lang.reflect.Proxy;
import java.nio.charset.StandardCharsets;
import java.time.Clock;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** Issue 25, item 4: the console bound to 0.0.0.0 used to answer plain HTTP from the network, with no warning. */
class PlainHttpRuleTest {

    private final List<String> problems = new ArrayList<>();

    @Test
    void plainHttpIsRefusedBeyondLoopbackUnlessOverTlsOrAllowed() throws Exception {
        Answer lan = request(false, "192.168.1.10", false);
        assertFalse(lan.passed, "the login page over plain HTTP from the network");
        assertEquals(403, lan.status);
        assertTrue(lan.body.contains("answers plain HTTP only on this machine (127.0.0.1), not at 192.168.1.10"), lan.body);
        assertEquals("nosniff", lan.headers.get("X-Content-Type-Options"), "the refusal carries the security headers");
        assertTrue(request(true, "192.168.1.10", false).passed, "over TLS");
        assertTrue(request(false, "127.0.0.1", false).passed, "on loopback");
        assertTrue(request(false, "0:0:0:0:0:0:0:1", false).passed, "on IPv6 loopback");
        assertTrue(request(false, "192.168.1.10", true).passed, "allowPlainHttpOffLoopback=true");
    }

    @Test
    void anEndpointBeyondLoopbackWithoutTlsIsAProblem() {
        assertEquals(Optional.empty(), PlainHttpRule.problem(List.of("http://127.0.0.1:8080/"), false));
        assertEquals(Optional.empty(), PlainHttpRule.problem(List.of("https://192.168.1.10:8443/", "http://[::1]:8080/"), false));
        String refused = PlainHttpRule.problem(List.of("http://0.0.0.0:8080/"), false).orElseThrow();
        assertTrue(refused.startsWith("the web console listens without TLS at http://0.0.0.0:8080/; it refuses"), refused);
        String allowed = PlainHttpRule.problem(List.of("http://192.168.1.10:8080/", "http://127.0.0.1:8080/"), true).orElseThrow();
        assertTrue(allowed.startsWith("the web console is served without TLS at http://192.168.1.10:8080/ "
                + "(allowPlainHttpOffLoopback=true"), allowed);
        WebSecurity security = security(false);
        security.problem(refused);
        assertEquals(List.of("Security: " + refused), problems);
    }

    private record Answer(boolean passed, int status, Map<String, String> headers, String body) {
    }

    private Answer request(boolean secure, String localAddress, boolean override) throws Exception {
        Map<String, Object> attributes = new HashMap<>();
        HttpServletRequest req = (HttpServletRequest) Proxy.newProxyInstance(getClass().getClassLoader(),
                new Class<?>[] {HttpServletRequest.class}, (p, m, a) -> switch (m.getName()) {
                    case "isSecure" -> secure;
                    case "getLocalAddr" -> localAddress;
                    case "getRequestURI" -> "/login.html";
                    case "getMethod" -> "GET";
                    case "getContentLengthLong" -> -1L;
                    case "setAttribute" -> attributes.put((String) a[0], a[1]);
                    default -> null;
                });
        Map<String, String> headers = new HashMap<>();
        int[] status = {200};
        ByteArrayOutputStream body = new ByteArrayOutputStream();
        ServletOutputStream out = new ServletOutputStream() {
            @Override
            public boolean isReady() {
                return true;
            }

            @Override
            public void setWriteListener(WriteListener listener) {
            }

            @Override
            public void write(int b) {
                body.write(b);
            }
        };
        HttpServletResponse resp = (HttpServletResponse) Proxy.newProxyInstance(getClass().getClassLoader(),
                new Class<?>[] {HttpServletResponse.class}, (p, m, a) -> {
                    switch (m.getName()) {
                        case "setHeader" -> headers.put((String) a[0], (String) a[1]);
                        case "setStatus" -> status[0] = (Integer) a[0];
                        case "getOutputStream" -> {
                            return out;
                        }
                        default -> {
                        }
                    }
                    return null;
                });
        boolean[] passed = {false};
        new SecurityFilter(security(override)).doFilter(req, resp, (rq, rs) -> passed[0] = true);
        return new Answer(passed[0], status[0], headers, body.toString(StandardCharsets.UTF_8));
    }

    private WebSecurity security(boolean override) {
        WebConfig config = (WebConfig) Proxy.newProxyInstance(getClass().getClassLoader(), new Class<?>[] {WebConfig.class},
                (p, m, a) -> m.getName().equals("allowPlainHttpOffLoopback") ? override : m.getDefaultValue());
        return new WebSecurity(null, config, Clock.systemUTC(), problems::add);
    }
}

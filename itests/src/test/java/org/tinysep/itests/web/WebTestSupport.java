package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.ops4j.pax.exam.CoreOptions.frameworkProperty;
import static org.ops4j.pax.exam.CoreOptions.mavenBundle;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.ServerSocket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ops4j.pax.exam.Option;
import org.tinysep.itests.TinySepTestSupport;

/**
 * Base of the web console tests: the usual platform plus the Felix HTTP service (Jetty 12) on a free port of
 * 127.0.0.1 and the two web bundles; helpers to log in and call the API with a real HTTP client.
 */
public abstract class WebTestSupport extends TinySepTestSupport {

    /** Passwords the tests set with tinysep:web-password. */
    protected static final String INSTALLER_PASSWORD = "installer-secret-1";
    protected static final String CAREGIVER_PASSWORD = "caregiver-secret-2";
    protected static final String HTTP_PORT = "org.osgi.service.http.port";
    /** As the launcher sets them (FrameworkConfig): the security headers on Jetty's own error pages (issue 25, item 8). */
    static final String ERROR_PAGE_HEADERS = "org.apache.felix.http.jetty.errorPageCustomHeaders";
    static final String ERROR_PAGE_HEADER_VALUES = "Content-Security-Policy=default-src 'none'; script-src 'self'; "
            + "style-src 'self'; img-src 'self' data:; connect-src 'self'; form-action 'self'; base-uri 'none'; "
            + "frame-ancestors 'none'##X-Content-Type-Options=nosniff##X-Frame-Options=DENY##Referrer-Policy=no-referrer"
            + "##Cache-Control=no-store";

    protected final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10))
            .followRedirects(HttpClient.Redirect.NEVER).build();

    /** A logged-in client: its session cookie and CSRF token. */
    protected record Login(String cookie, String csrf, String setCookie) {
    }

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.add(frameworkProperty(HTTP_PORT).value(Integer.toString(freePort())));
        o.add(frameworkProperty("org.apache.felix.http.host").value("127.0.0.1"));
        o.add(frameworkProperty(ERROR_PAGE_HEADERS).value(ERROR_PAGE_HEADER_VALUES));
        o.add(mavenBundle("org.apache.felix", "org.apache.felix.http.servlet-api").versionAsInProject().startLevel(3));
        o.add(mavenBundle("commons-io", "commons-io").versionAsInProject().startLevel(3));
        o.add(mavenBundle("commons-fileupload", "commons-fileupload").versionAsInProject().startLevel(3));
        o.add(mavenBundle("org.apache.felix", "org.apache.felix.http.jetty12").versionAsInProject().startLevel(3));
        o.add(reactorBundle("org.tinysep.web.api", 5));
        o.add(reactorBundle("org.tinysep.web.console", 5));
        return o;
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        try { // House Information on a fresh file, never the working folder
            configs.put("org.tinysep.houseinformation", Map.of("file",
                    Files.createTempDirectory("tinysep-web-house-").resolve("house.xml").toString()));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return configs;
    }

    /** Sends {@code bytes} as the body with {@code contentType} (e.g. a bundle jar). */
    protected HttpResponse<String> upload(String path, byte[] bytes, String contentType, Login login, boolean csrf) {
        HttpRequest.Builder b = HttpRequest.newBuilder(URI.create(base() + path)).timeout(Duration.ofSeconds(60))
                .header("Content-Type", contentType).POST(HttpRequest.BodyPublishers.ofByteArray(bytes));
        HttpResponse<String> r = exchange(as(b, login, csrf));
        log.info("POST {} ({} bytes) -> {} {}", path, bytes.length, r.statusCode(), r.body());
        return r;
    }

    /** @return {@code b} with the login's session cookie (if any) and, with {@code csrf}, its CSRF header */
    private static HttpRequest.Builder as(HttpRequest.Builder b, Login login, boolean csrf) {
        if (login != null) {
            b.header("Cookie", login.cookie());
            if (csrf) {
                b.header("X-CSRF-Token", login.csrf());
            }
        }
        return b;
    }

    /**
     * Sends the request and reads the answer as text: the one place {@link #call} and {@link #upload} talk to the
     * console; an I/O failure becomes unchecked, an interruption an assertion error.
     */
    private HttpResponse<String> exchange(HttpRequest.Builder request) {
        try {
            return http.send(request.build(), HttpResponse.BodyHandlers.ofString());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
    }

    /** @return the bytes of a reactor bundle's jar */
    protected static byte[] reactorJar(String artifactId) {
        try {
            return Files.readAllBytes(java.nio.file.Path.of(URI.create(bundleUrl(artifactId))));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static int freePort() {
        try (ServerSocket s = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** @return {@code http://127.0.0.1:<port>}, once the console answers */
    protected String base() {
        String base = "http://127.0.0.1:" + context.getProperty(HTTP_PORT);
        await(Duration.ofSeconds(30), () -> status(send("GET", base + "/login.html", null, null, null)) == 200,
                "the web console at " + base);
        return base;
    }

    /** Sets both passwords in the shell, as a user would. */
    protected void setPasswords() {
        awaitService(org.apache.felix.service.command.CommandProcessor.class, null, TIMEOUT);
        await(TIMEOUT, () -> {
            try {
                return shell("tinysep:web-password installer " + INSTALLER_PASSWORD).contains("set");
            } catch (AssertionError e) {
                return false; // the command is not registered yet
            }
        }, "tinysep:web-password");
        shell("tinysep:web-password caregiver " + CAREGIVER_PASSWORD);
    }

    protected Login login(String user, String password) {
        HttpResponse<String> r = call("POST", "/api/session", "{\"user\":\"" + user + "\",\"password\":\"" + password + "\"}", null, false);
        assertEquals(r.body(), 200, r.statusCode());
        String setCookie = r.headers().firstValue("Set-Cookie").orElseThrow();
        Matcher m = Pattern.compile("\"csrf\":\"([^\"]+)\"").matcher(r.body());
        if (!m.find()) {
            throw new AssertionError("no CSRF token in " + r.body());
        }
        return new Login(setCookie.substring(0, setCookie.indexOf(';')), m.group(1), setCookie);
    }

    /** Calls the console: {@code body} as JSON; with {@code csrf}, the login's CSRF header on changes. */
    protected HttpResponse<String> call(String method, String path, String body, Login login, boolean csrf) {
        HttpRequest.Builder b = as(HttpRequest.newBuilder(URI.create(base() + path)).timeout(Duration.ofSeconds(30)),
                login, csrf);
        if (body != null) {
            b.header("Content-Type", "application/json");
        }
        b.method(method, body == null ? HttpRequest.BodyPublishers.noBody() : HttpRequest.BodyPublishers.ofString(body));
        HttpResponse<String> r = exchange(b);
        log.info("{} {} -> {} {}", method, path, r.statusCode(), r.body().length() > 300 ? r.body().substring(0, 300) + "…" : r.body());
        return r;
    }

    private HttpResponse<String> send(String method, String url, String body, String cookie, String csrf) {
        try {
            return http.send(HttpRequest.newBuilder(URI.create(url)).timeout(Duration.ofSeconds(10)).GET().build(),
                    HttpResponse.BodyHandlers.ofString());
        } catch (IOException e) {
            return null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
    }

    private static int status(HttpResponse<?> r) {
        return r == null ? -1 : r.statusCode();
    }

    /** Waits until the API lists a device of {@code type} for node {@code address}; @return its UID */
    protected String awaitDevice(Login login, String type, String address) {
        Pattern p = Pattern.compile("\\{\"uid\":\"([^\"]+)\",\"name\":\"[^\"]*\",\"type\":\"" + type
                + "\",[^{]*\\{[^}]*\\},[^}]*?\"nodeAddress\":\"" + Pattern.quote(address) + "\"");
        String[] uid = new String[1];
        await(Duration.ofSeconds(20), () -> {
            Matcher m = p.matcher(call("GET", "/api/devices", null, login, false).body());
            if (m.find()) {
                uid[0] = m.group(1);
                return true;
            }
            return false;
        }, type + " device of node " + address + " in GET /api/devices");
        return uid[0];
    }

    /**
     * Sends {@code request} (a whole HTTP/1.1 request, exactly as given) over a plain socket bound to the source
     * address {@code from} (any 127.x.y.z is this machine), to the console on 127.0.0.1, and reads the answer until the
     * server closes the connection (at most 10 s).
     *
     * @return the answer as text: status line, headers, body
     */
    protected String raw(String from, String request) {
        base(); // the console is up
        int port = Integer.parseInt(context.getProperty(HTTP_PORT));
        try (java.net.Socket socket = new java.net.Socket()) {
            socket.bind(new java.net.InetSocketAddress(from, 0));
            socket.connect(new java.net.InetSocketAddress("127.0.0.1", port), 10_000);
            socket.setSoTimeout(10_000);
            socket.getOutputStream().write(request.getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
            socket.getOutputStream().flush();
            String answer = new String(socket.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            log.info("raw from {}: {} -> {}", from, request.lines().findFirst().orElse(""),
                    answer.lines().findFirst().orElse("(nothing)"));
            return answer;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** @return the answer's status code to a login as {@code user} sent from the source address {@code from} */
    protected int loginFrom(String from, String user, String password) {
        String body = "{\"user\":\"" + user + "\",\"password\":\"" + password + "\"}";
        String answer = raw(from, "POST /api/session HTTP/1.1\r\nHost: 127.0.0.1:" + context.getProperty(HTTP_PORT)
                + "\r\nContent-Type: application/json\r\nContent-Length: " + body.length()
                + "\r\nConnection: close\r\n\r\n" + body);
        return Integer.parseInt(answer.substring(9, 12));
    }

    protected static String field(String json, String name) {
        Matcher m = Pattern.compile("\"" + name + "\":\"([^\"]*)\"").matcher(json);
        if (!m.find()) {
            throw new AssertionError("no " + name + " in " + json);
        }
        return m.group(1);
    }
}

package org.tinysep.itests.web;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Base64;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Debian's headless Chromium driven over the Chrome DevTools Protocol (a WebSocket, {@code java.net.http}; no
 * WebDriver, no download): open a page, run JavaScript in it, wait for conditions, take screenshots. One fresh,
 * empty profile per instance, deleted on {@link #close()}.
 */
public final class Chromium implements AutoCloseable {

    private static final List<String> CANDIDATES = List.of("/usr/bin/chromium", "/usr/bin/chromium-browser",
            "/usr/bin/google-chrome");

    private final Process process;
    private final Path profile;
    private final WebSocket socket;
    private final AtomicInteger ids = new AtomicInteger();
    private final Map<Integer, CompletableFuture<String>> pending = new ConcurrentHashMap<>();

    private Chromium(Process process, Path profile, WebSocket socket) {
        this.process = process;
        this.profile = profile;
        this.socket = socket;
    }

    /** @return the Chromium binary, or null when none is installed (scripts/install-deps.sh installs it) */
    public static Path binary() {
        return CANDIDATES.stream().map(Path::of).filter(Files::isExecutable).findFirst().orElse(null);
    }

    public static Chromium start(Duration timeout) throws Exception {
        Path bin = binary();
        if (bin == null) {
            throw new AssertionError("no Chromium: run scripts/install-deps.sh (apt-get install chromium)");
        }
        Path profile = Files.createTempDirectory("tinysep-chromium-");
        Process p = new ProcessBuilder(bin.toString(), "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--disable-extensions", "--hide-scrollbars", "--window-size=1280,860", "--remote-debugging-port=0",
                "--remote-debugging-address=127.0.0.1", "--user-data-dir=" + profile, "about:blank")
                .redirectErrorStream(true).redirectOutput(profile.resolveSibling(profile.getFileName() + ".log").toFile())
                .start();
        Path portFile = profile.resolve("DevToolsActivePort");
        long deadline = System.nanoTime() + timeout.toNanos();
        while (!(Files.exists(portFile) && Files.readAllLines(portFile).size() >= 2)) {
            if (System.nanoTime() > deadline || !p.isAlive()) {
                p.destroyForcibly();
                throw new AssertionError("Chromium did not open its DevTools port within " + timeout.toSeconds() + " s");
            }
            Thread.sleep(50);
        }
        int port = Integer.parseInt(Files.readAllLines(portFile).get(0).strip());
        HttpClient http = HttpClient.newHttpClient();
        String pageSocket = null;
        while (pageSocket == null) {
            String list = http.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + port + "/json/list")).build(),
                    HttpResponse.BodyHandlers.ofString()).body();
            Matcher m = Pattern.compile("\"type\":\\s*\"page\"[^}]*?\"webSocketDebuggerUrl\":\\s*\"([^\"]+)\"").matcher(list);
            if (m.find()) {
                pageSocket = m.group(1);
            } else if (System.nanoTime() > deadline) {
                p.destroyForcibly();
                throw new AssertionError("Chromium has no page target: " + list);
            } else {
                Thread.sleep(50);
            }
        }
        Chromium[] self = new Chromium[1];
        StringBuilder partial = new StringBuilder();
        WebSocket ws = http.newWebSocketBuilder().buildAsync(URI.create(pageSocket), new WebSocket.Listener() {
            @Override
            public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
                partial.append(data);
                if (last) {
                    String message = partial.toString();
                    partial.setLength(0);
                    if (self[0] != null) {
                        self[0].received(message);
                    }
                }
                webSocket.request(1);
                return null;
            }
        }).get(timeout.toSeconds(), TimeUnit.SECONDS);
        self[0] = new Chromium(p, profile, ws);
        self[0].command("Page.enable", "{}");
        self[0].command("Runtime.enable", "{}");
        return self[0];
    }

    private void received(String message) {
        Matcher m = Pattern.compile("^\\{\"id\":(\\d+),").matcher(message);
        if (m.find()) {
            CompletableFuture<String> f = pending.remove(Integer.parseInt(m.group(1)));
            if (f != null) {
                f.complete(message);
            }
        }
    }

    /** Sends one DevTools command; @return its raw JSON answer */
    String command(String method, String paramsJson) {
        int id = ids.incrementAndGet();
        CompletableFuture<String> answer = new CompletableFuture<>();
        pending.put(id, answer);
        socket.sendText("{\"id\":" + id + ",\"method\":\"" + method + "\",\"params\":" + paramsJson + "}", true).join();
        try {
            String a = answer.get(60, TimeUnit.SECONDS);
            if (a.contains("\"error\":{")) {
                throw new AssertionError(method + " failed: " + a);
            }
            return a;
        } catch (Exception e) {
            throw new AssertionError(method + ": no answer from Chromium: " + e, e);
        }
    }

    public void navigate(String url) {
        command("Page.navigate", "{\"url\":" + quote(url) + "}");
    }

    /** Runs {@code expression} in the page (promises awaited); @return its value as JSON text */
    public String eval(String expression) {
        String answer = command("Runtime.evaluate", "{\"expression\":" + quote("JSON.stringify(" + expression + ")")
                + ",\"awaitPromise\":true,\"returnByValue\":true}");
        if (answer.contains("\"exceptionDetails\"")) {
            throw new AssertionError("JavaScript failed: " + expression + " -> " + answer);
        }
        Matcher m = Pattern.compile("\"value\":(\"(?:[^\"\\\\]|\\\\.)*\")").matcher(answer);
        return m.find() ? unquote(m.group(1)) : "undefined";
    }

    /**
     * The page's weight and time to first render, from the browser's performance entries: {@code pageBytes} and
     * {@code pageFiles} (the page and its static files), {@code apiBytes} (API answers, not streams),
     * {@code firstContentfulPaintMs}, {@code eventsShownMs} (the event log page's own mark) and
     * {@code domContentLoadedMs}.
     *
     * @return those figures as JSON text
     */
    public String pageMetrics() {
        return eval("(() => { const n = performance.getEntriesByType('navigation')[0];"
                + " const r = performance.getEntriesByType('resource');"
                + " const stat = r.filter(e => !e.name.includes('/api/'));"
                + " const api = r.filter(e => e.name.includes('/api/') && !e.name.includes('/api/stream/'));"
                + " const paint = performance.getEntriesByName('first-contentful-paint')[0];"
                + " const shown = performance.getEntriesByName('events-shown')[0];"
                + " return {pageBytes: n.transferSize + stat.reduce((s, e) => s + e.transferSize, 0),"
                + " pageFiles: 1 + stat.length, apiBytes: api.reduce((s, e) => s + e.transferSize, 0),"
                + " firstContentfulPaintMs: paint ? Math.round(paint.startTime) : null,"
                + " eventsShownMs: shown ? Math.round(shown.startTime) : null,"
                + " domContentLoadedMs: Math.round(n.domContentLoadedEventEnd)}; })()");
    }

    /**
     * After a failed step of a browser test: saves a screenshot as {@code target/<folder>/failure-<step>.png}.
     *
     * @return what to log: where the screenshot is, or that none could be taken
     */
    public String failureScreenshot(String folder, String step) {
        Path file = Path.of("target", folder, "failure-" + step.replace(' ', '-') + ".png").toAbsolutePath();
        try {
            screenshot(file);
            return "screenshot: " + file;
        } catch (AssertionError | RuntimeException e) {
            return "no screenshot could be taken (" + e.getMessage() + ")";
        }
    }

    /** Waits until {@code condition} (JavaScript) is true in the page, checking every 100 ms. */
    public void waitFor(String condition, Duration timeout, String what) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        String last = "";
        while (System.nanoTime() < deadline) {
            try {
                if ("true".equals(eval("!!(" + condition + ")"))) {
                    return;
                }
            } catch (AssertionError e) {
                last = e.getMessage(); // e.g. the page is between two documents
            }
            Thread.sleep(100);
        }
        throw new AssertionError("Timed out after " + timeout.toSeconds() + " s waiting for " + what + " in the browser "
                + "(at " + eval("location.href") + ") " + last);
    }

    /** Chooses {@code file} in the page's file input {@code selector} (as a user picking it in the dialog). */
    void setFile(String selector, Path file) {
        Matcher root = Pattern.compile("\"root\":\\{\"nodeId\":(\\d+)").matcher(command("DOM.getDocument", "{\"depth\":0}"));
        if (!root.find()) {
            throw new AssertionError("no document node");
        }
        Matcher node = Pattern.compile("\"nodeId\":(\\d+)").matcher(command("DOM.querySelector",
                "{\"nodeId\":" + root.group(1) + ",\"selector\":" + quote(selector) + "}"));
        if (!node.find() || node.group(1).equals("0")) {
            throw new AssertionError("no element " + selector + " in the page");
        }
        command("DOM.setFileInputFiles", "{\"files\":[" + quote(file.toAbsolutePath().toString()) + "],\"nodeId\":" + node.group(1) + "}");
    }

    public void screenshot(Path file) {
        write(file, command("Page.captureScreenshot", "{\"format\":\"png\",\"captureBeyondViewport\":false}"));
    }

    /** A picture of the page's top {@code maxHeight} pixels (or the whole page when shorter), the window's width. */
    void screenshot(Path file, int maxHeight) {
        int height = Math.min(maxHeight, Integer.parseInt(eval("document.documentElement.scrollHeight")));
        int width = Integer.parseInt(eval("document.documentElement.clientWidth"));
        write(file, command("Page.captureScreenshot", "{\"format\":\"png\",\"captureBeyondViewport\":true,"
                + "\"clip\":{\"x\":0,\"y\":0,\"width\":" + width + ",\"height\":" + height + ",\"scale\":1}}"));
    }

    private static void write(Path file, String answer) {
        Matcher m = Pattern.compile("\"data\":\"([^\"]+)\"").matcher(answer);
        if (!m.find()) {
            throw new AssertionError("no screenshot data");
        }
        try {
            Files.createDirectories(file.getParent());
            Files.write(file, Base64.getDecoder().decode(m.group(1)));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    public static String quote(String s) {
        StringBuilder sb = new StringBuilder("\"");
        for (char c : s.toCharArray()) {
            switch (c) {
                case '"' -> sb.append("\\\"");
                case '\\' -> sb.append("\\\\");
                case '\n' -> sb.append("\\n");
                default -> {
                    if (c < 0x20) {
                        sb.append(String.format("\\u%04x", (int) c));
                    } else {
                        sb.append(c);
                    }
                }
            }
        }
        return sb.append('"').toString();
    }

    static String unquote(String literal) {
        StringBuilder sb = new StringBuilder();
        for (int i = 1; i < literal.length() - 1; i++) {
            char c = literal.charAt(i);
            if (c != '\\') {
                sb.append(c);
                continue;
            }
            char e = literal.charAt(++i);
            switch (e) {
                case 'n' -> sb.append('\n');
                case 't' -> sb.append('\t');
                case 'r' -> sb.append('\r');
                case 'b' -> sb.append('\b');
                case 'f' -> sb.append('\f');
                case 'u' -> {
                    sb.append((char) Integer.parseInt(literal.substring(i + 1, i + 5), 16));
                    i += 4;
                }
                default -> sb.append(e);
            }
        }
        return sb.toString();
    }

    @Override
    public void close() {
        try {
            socket.sendClose(WebSocket.NORMAL_CLOSURE, "").orTimeout(2, TimeUnit.SECONDS);
        } catch (RuntimeException ignored) {
            // closing anyway
        }
        process.descendants().forEach(ProcessHandle::destroyForcibly);
        process.destroyForcibly();
        try {
            process.waitFor(10, TimeUnit.SECONDS);
            try (Stream<Path> files = Files.walk(profile)) {
                files.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
            }
        } catch (Exception ignored) {
            // a temp folder left behind
        }
    }
}

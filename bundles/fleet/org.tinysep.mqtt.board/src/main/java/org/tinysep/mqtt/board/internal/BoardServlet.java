package org.tinysep.mqtt.board.internal;

import jakarta.servlet.Servlet;
import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Clock;
import java.util.Map;
import java.util.Optional;
import org.eclipse.paho.mqttv5.common.MqttException;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicyOption;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.web.BoardRoutes;
import org.tinysep.api.web.WebConsole;
import org.tinysep.json.JsonWriter;

/**
 * The central alert board: runs the board ({@link Central}) with its configuration and serves it under
 * {@code /board/} on the web console's HTTP service: the page ({@code /board/}, {@code board.js}, the console's
 * stylesheet), its JSON ({@code GET /board/api/flats}) and acknowledging ({@code POST
 * /board/api/flats/<flat>/alerts/<id>/acknowledge}, body {@code {"by":"…"}} optional; the routes are
 * {@link BoardRoutes}, shared with the login filter). The web console's login filter (bundle org.tinysep.web.api)
 * guards every path of this context: without its mark ({@link WebConsole#ROLE_ATTRIBUTE}), this servlet answers 503.
 */
@Component(service = Servlet.class, configurationPid = "org.tinysep.mqtt.board", property = {
    "osgi.http.whiteboard.servlet.pattern=" + BoardRoutes.SERVLET_PATTERN,
    "osgi.http.whiteboard.servlet.name=tinysep-central-board"
})
@Designate(ocd = BoardConfig.class)
public final class BoardServlet extends HttpServlet {

    private static final long serialVersionUID = 1L;
    private static final Logger LOG = LoggerFactory.getLogger(BoardServlet.class);
    private static final Map<String, String> FILES = Map.of("/", "board.html", "/board.js", "board.js");

    private transient Central central;

    @Reference(cardinality = ReferenceCardinality.OPTIONAL, policyOption = ReferencePolicyOption.GREEDY)
    private transient EventLog events;

    @Activate
    void activate(BundleContext context, BoardConfig config) throws MqttException {
        central = new Central(config, Clock.systemUTC(), null, var(context), this::problem);
        LOG.info("Central board at /board/: {}", config.brokerUrl().isBlank() ? "idle, no broker configured"
                : "following " + config.topicPrefix() + "/+/… on " + BoardClient.shown(config.brokerUrl()));
    }

    /** @return {@code tinysep.var}, else {@code tinysep.home/var}, else the bundle's data area */
    private static Path var(BundleContext context) {
        String var = context.getProperty("tinysep.var");
        String home = context.getProperty("tinysep.home");
        if (var != null && !var.isBlank()) {
            return Path.of(var.strip());
        }
        if (home != null && !home.isBlank()) {
            return Path.of(home.strip(), "var");
        }
        File data = context.getDataFile("var");
        return data == null ? Path.of("var").toAbsolutePath() : data.toPath();
    }

    private void problem(String message) {
        EventLog log = events;
        if (log != null) {
            log.record(EventKind.PROBLEM, "CentralBoard", message);
        }
    }

    @Deactivate
    void deactivate() {
        central.close();
    }

    @Override
    protected void doGet(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        if (!loggedIn(req, resp)) {
            return;
        }
        String path = req.getPathInfo() == null ? "/" : req.getPathInfo();
        if (path.equals("/api/flats")) {
            send(resp, 200, central.json());
            return;
        }
        String file = FILES.get(path);
        if (file == null) {
            resp.sendError(404, "no such page");
            return;
        }
        byte[] bytes;
        try (InputStream in = BoardServlet.class.getResourceAsStream("/board/" + file)) {
            bytes = in.readAllBytes();
        }
        resp.setContentType(file.endsWith(".js") ? "text/javascript;charset=utf-8" : "text/html;charset=utf-8");
        resp.setHeader("Cache-Control", "no-cache");
        resp.setContentLength(bytes.length);
        resp.getOutputStream().write(bytes);
    }

    @Override
    protected void doPost(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        if (!loggedIn(req, resp)) {
            return;
        }
        Optional<BoardRoutes.Acknowledge> ack = BoardRoutes.acknowledge(req.getPathInfo());
        if (ack.isEmpty()) {
            send(resp, 404, error("no such call"));
            return;
        }
        String by = null;
        byte[] body = req.getInputStream().readNBytes(4096);
        try {
            if (body.length > 0) {
                by = Payloads.fields(new String(body, StandardCharsets.UTF_8)).get("by");
            }
            String words = central.acknowledge(ack.get().flat(), ack.get().alertId(), by);
            send(resp, 200, new JsonWriter().open('{').field("ok", true).field("explanation", words).close('}')
                    .toString());
        } catch (IllegalArgumentException e) {
            send(resp, 404, error(e.getMessage()));
        } catch (IllegalStateException e) {
            send(resp, 409, error(e.getMessage()));
        } catch (MqttException e) {
            send(resp, 503, error("the broker did not take the acknowledgement: " + e.getMessage()));
        }
    }

    private static boolean loggedIn(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        if (req.getAttribute(WebConsole.ROLE_ATTRIBUTE) == null) {
            send(resp, 503, error("the web console's login (bundle org.tinysep.web.api) is not running: the board is closed"));
            return false;
        }
        return true;
    }

    private static String error(String words) {
        return new JsonWriter().open('{').field("error", words).close('}').toString();
    }

    private static void send(HttpServletResponse resp, int status, String json) throws IOException {
        byte[] bytes = json.getBytes(StandardCharsets.UTF_8);
        resp.setStatus(status);
        resp.setContentType("application/json;charset=utf-8");
        resp.setHeader("Cache-Control", "no-store");
        resp.setContentLength(bytes.length);
        resp.getOutputStream().write(bytes);
    }
}

package org.tinysep.web.api.internal;

import jakarta.servlet.Servlet;
import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.osgi.framework.BundleContext;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.component.annotations.ReferenceCardinality;
import org.osgi.service.component.annotations.ReferencePolicy;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.api.log.PacketLog;
import org.tinysep.api.packet.PacketDescriber;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.api.web.WebConsole;
import org.tinysep.json.JsonWriter;

/**
 * The JSON API under {@code /api/} (docs/web-api.md). Login, CSRF and roles are checked before any request gets
 * here ({@link SecurityFilter}); this servlet routes, reads bodies (at most {@value #MAX_BODY} bytes) and turns
 * {@link ApiException}s into {@code {"error": "..."}} answers.
 */
@Component(service = Servlet.class, property = {
    "osgi.http.whiteboard.servlet.pattern=/api/*",
    "osgi.http.whiteboard.servlet.name=tinysep-web-api"
})
public final class ApiServlet extends HttpServlet {

    private static final long serialVersionUID = 1L;
    private static final Logger LOG = LoggerFactory.getLogger(ApiServlet.class);
    static final int MAX_BODY = 64 * 1024;

    private final transient EventLog events;
    private final transient PacketLog packets;
    private final transient PlatformView platform;
    private final transient SessionApi session;
    private final transient DevicesApi devices;
    private final transient RoomsApi rooms;
    private final transient LogsApi logs;
    private final transient CaregiverApi caregiver;
    private final transient LiveStreams streams;
    private final transient ApplicationsApi applications;
    private final transient TimelineApi timeline;
    private final transient AlertsApi alerts;
    private final transient SensorsApi sensors;
    private final transient PacketDescriptions descriptions = new PacketDescriptions();

    @Activate
    public ApiServlet(BundleContext context, @Reference WebSecurity security, @Reference(name = "eventLog") EventLog events,
            @Reference(name = "packetLog") PacketLog packets) {
        this.events = events;
        this.packets = packets;
        this.platform = new PlatformView(context);
        this.session = new SessionApi(security);
        this.devices = new DevicesApi(platform);
        this.rooms = new RoomsApi(platform);
        this.logs = new LogsApi(platform, descriptions);
        this.caregiver = new CaregiverApi(platform);
        java.nio.file.Path web = org.tinysep.device.support.files.StateFolder.resolveOrDataArea(null, context, "web");
        this.applications = new ApplicationsApi(context, platform,
                (web == null ? java.nio.file.Path.of("tinysep-web") : web).resolve("uploads").toAbsolutePath());
        this.timeline = new TimelineApi(platform);
        this.alerts = new AlertsApi(platform);
        this.sensors = new SensorsApi(platform, java.time.ZoneId.systemDefault());
        NameCache names = new NameCache(platform);
        this.streams = new LiveStreams(
                new LiveFeed<EventEntry>("events", events::recent, EventEntry::sequence,
                        e -> JsonWriter.write(LogsApi.event(e, names.get()))),
                new LiveFeed<PacketEntry>("packets", packets::recent, PacketEntry::sequence,
                        p -> JsonWriter.write(LogsApi.packet(p, descriptions))), security.sessions());
    }

    /** The protocols' packet describers (whiteboard), as their bus radios come and go. */
    @Reference(cardinality = ReferenceCardinality.MULTIPLE, policy = ReferencePolicy.DYNAMIC)
    void addDescriber(PacketDescriber d) {
        descriptions.add(d);
    }

    void removeDescriber(PacketDescriber d) {
        descriptions.remove(d);
    }

    @Deactivate
    void deactivate() {
        streams.close();
    }

    @Override
    protected void service(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        String path = req.getPathInfo() == null ? "" : req.getPathInfo();
        List<String> p = Arrays.stream(path.split("/")).filter(s -> !s.isEmpty()).toList();
        String method = req.getMethod();
        try {
            if (p.size() == 2 && p.get(0).equals("stream") && method.equals("GET")) {
                streams.serve(p.get(1), req, resp);
                return;
            }
            Object answer = route(method, p, req, resp);
            send(resp, 200, answer);
        } catch (ApiException e) {
            send(resp, e.status(), Map.of("error", e.getMessage()));
        } catch (RuntimeException e) {
            LOG.warn("{} /api{} failed", method, path, e);
            send(resp, 500, Map.of("error", "the platform could not answer: " + e));
        }
    }

    private Object route(String method, List<String> p, HttpServletRequest req, HttpServletResponse resp) throws IOException {
        String head = p.isEmpty() ? "" : p.get(0);
        int n = p.size();
        switch (head) {
            case "session" -> {
                if (n == 1) {
                    return switch (method) {
                        case "GET" -> session.current(req);
                        case "POST" -> session.login(req, resp, body(req));
                        case "DELETE" -> session.logout(req, resp);
                        default -> throw notAllowed(method);
                    };
                }
            }
            case "devices" -> {
                if (n == 1 && method.equals("GET")) {
                    return devices.list();
                }
                if (n == 2 && method.equals("GET")) {
                    return devices.one(p.get(1));
                }
                if (n == 4 && p.get(2).equals("parameters") && method.equals("PUT")) {
                    return devices.setParameter(p.get(1), p.get(3), body(req).get("value"));
                }
                if (n == 4 && p.get(2).equals("functions") && method.equals("POST")) {
                    return devices.invoke(p.get(1), p.get(3));
                }
            }
            case "drivers" -> {
                if (n == 1 && method.equals("GET")) {
                    return devices.drivers();
                }
            }
            case "applications" -> {
                return applications.route(method, p, req);
            }
            case "alerts" -> {
                if (n == 1 && method.equals("GET")) {
                    return alerts.status();
                }
                if (n == 3 && p.get(2).equals("acknowledge") && method.equals("POST")) {
                    return alerts.acknowledge(p.get(1), String.valueOf(req.getAttribute(WebConsole.ROLE_ATTRIBUTE)));
                }
            }
            case "rooms" -> {
                if (n == 1 && method.equals("GET")) {
                    return rooms.list();
                }
                if (n == 1 && method.equals("POST")) {
                    return rooms.add(body(req));
                }
                if (n == 2 && method.equals("PUT")) {
                    return rooms.update(p.get(1), body(req));
                }
                if (n == 2 && method.equals("DELETE")) {
                    return rooms.remove(p.get(1));
                }
                if (n == 4 && p.get(2).equals("neighbours") && (method.equals("PUT") || method.equals("DELETE"))) {
                    return rooms.link(p.get(1), p.get(3), method.equals("PUT"));
                }
            }
            case "events" -> {
                if (n == 1 && method.equals("GET")) {
                    return logs.events(events, req.getParameterMap());
                }
            }
            case "packets" -> {
                if (n == 1 && method.equals("GET")) {
                    return logs.packets(packets, req.getParameterMap());
                }
            }
            case "caregiver" -> {
                Instant now = platform.withService(TimeControllerProvider.class, TimeControllerProvider::now)
                        .orElse(Instant.now());
                if (n == 1 && method.equals("GET")) {
                    return caregiver.status(events, now);
                }
                if (n == 2 && p.get(1).equals("timeline") && method.equals("GET")) {
                    return timeline.timeline(events, now, req.getParameterMap());
                }
                if (n == 2 && p.get(1).equals("sensors") && method.equals("GET")) {
                    return sensors.status(now);
                }
            }
            default -> {
                // not found below
            }
        }
        throw ApiException.notFound("no such API call: " + method + " /api/" + String.join("/", p));
    }

    private static ApiException notAllowed(String method) {
        return new ApiException(405, method + " is not allowed here");
    }

    static Map<String, String> body(HttpServletRequest req) throws IOException {
        String type = req.getContentType() == null ? "" : req.getContentType().toLowerCase(java.util.Locale.ROOT);
        if (!type.startsWith("application/json")) {
            throw new ApiException(415, "send the request body as JSON (Content-Type: application/json)");
        }
        try (InputStream in = req.getInputStream()) {
            byte[] bytes = in.readNBytes(MAX_BODY + 1);
            if (bytes.length > MAX_BODY) {
                throw new ApiException(413, "the request body is larger than " + MAX_BODY + " bytes");
            }
            return JsonBody.parse(new String(bytes, StandardCharsets.UTF_8));
        }
    }

    static void send(HttpServletResponse resp, int status, Object answer) throws IOException {
        byte[] bytes = JsonWriter.write(answer).getBytes(StandardCharsets.UTF_8);
        resp.setStatus(status);
        resp.setContentType("application/json;charset=utf-8");
        resp.setHeader("Cache-Control", "no-store");
        resp.setContentLength(bytes.length);
        resp.getOutputStream().write(bytes);
    }
}

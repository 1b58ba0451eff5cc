package org.tinysep.web.console.internal;

import jakarta.servlet.Servlet;
import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;
import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.util.Map;
import java.util.regex.Pattern;
import org.osgi.service.component.annotations.Component;
import org.tinysep.api.web.WebConsole;

/**
 * Serves the console's static files (the bundle's {@code /web/} folder) at the root of the HTTP service:
 * {@code /} is the event log page. Only plain names ({@code [a-z0-9-]+.(html|css|js|svg)}) are served, so no
 * path can reach outside the folder. The web API's login filter runs first; a page other than the login page
 * is refused (503) when that filter has not marked the request as logged in ({@link WebConsole}), so the pages are never open
 * while the API bundle is stopped.
 */
@Component(service = Servlet.class, property = {
    "osgi.http.whiteboard.servlet.pattern=/",
    "osgi.http.whiteboard.servlet.name=tinysep-web-console"
})
public final class PagesServlet extends HttpServlet {

    private static final long serialVersionUID = 1L;
    private static final Pattern NAME = Pattern.compile("/[a-z0-9-]+\\.(html|css|js|svg)");
    private static final Map<String, String> TYPES = Map.of("html", "text/html;charset=utf-8",
            "css", "text/css;charset=utf-8", "js", "text/javascript;charset=utf-8", "svg", "image/svg+xml");

    @Override
    protected void doGet(HttpServletRequest req, HttpServletResponse resp) throws IOException {
        String path = req.getRequestURI() == null || req.getRequestURI().equals("/") ? "/index.html" : req.getRequestURI();
        if (!NAME.matcher(path).matches()) {
            resp.sendError(404, "no such page");
            return;
        }
        URL resource = PagesServlet.class.getResource("/web" + path);
        if (resource == null) {
            resp.sendError(404, "no such page");
            return;
        }
        if (!WebConsole.PUBLIC_PAGES.contains(path) && req.getAttribute(WebConsole.ROLE_ATTRIBUTE) == null) {
            resp.sendError(503, "the web console's login (bundle org.tinysep.web.api) is not running");
            return;
        }
        byte[] bytes;
        try (InputStream in = resource.openStream()) {
            bytes = in.readAllBytes();
        }
        resp.setContentType(TYPES.get(path.substring(path.lastIndexOf('.') + 1)));
        resp.setHeader("Cache-Control", "no-cache");
        resp.setContentLength(bytes.length);
        resp.getOutputStream().write(bytes);
    }
}

package org.tinysep.web.api.internal;

import org.tinysep.device.support.lifecycle.Safely;
import jakarta.servlet.http.HttpServletRequest;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.tinysep.api.device.Driver;
import org.tinysep.api.drivers.ApplicationEntry;

/**
 * {@code /api/applications}: the drivers list of thesis 3.4 as the console shows it. An application is a bundle at
 * start level {@value #APP_LEVEL} or above (bus radios, drivers, services), or an entry of the drivers list that is
 * not installed (e.g. disabled). Upload installs a new application or updates the installed one of the same
 * symbolic name; uninstall removes it; enable, disable and reload go through the drivers list. Platform bundles
 * (below level {@value #APP_LEVEL}) and the console's own are refused (409).
 */
final class ApplicationsApi {

    static final int APP_LEVEL = 5;

    private final BundleContext context;
    private final PlatformView platform;
    private final DriversListAccess list;
    private final Path uploads;
    private final ApplicationInstaller installer;

    ApplicationsApi(BundleContext context, PlatformView platform, Path uploads) {
        this.context = context;
        this.platform = platform;
        this.list = new DriversListAccess(platform);
        this.uploads = uploads;
        this.installer = new ApplicationInstaller(context, uploads, list, this::json);
    }

    /** Routes {@code /api/applications…} ({@code p} = the path's parts, the first being "applications"). */
    Object route(String method, List<String> p, HttpServletRequest req) throws IOException {
        int n = p.size();
        if (n == 1 && method.equals("GET")) {
            return list("true".equals(req.getParameter("all")));
        }
        if (n == 1 && method.equals("POST")) {
            return installer.upload(JarUpload.read(req), "true".equals(req.getParameter("replaceWatching")));
        }
        if (n == 2 && p.get(1).equals("reload") && method.equals("POST")) {
            return reload();
        }
        if (n == 2 && method.equals("DELETE")) {
            return installer.remove(p.get(1));
        }
        if (n == 3 && method.equals("POST") && (p.get(2).equals("enable") || p.get(2).equals("disable"))) {
            return setEnabled(p.get(1), p.get(2).equals("enable"));
        }
        throw ApiException.notFound("no such API call: " + method + " /api/" + String.join("/", p));
    }

    /**
     * GET /api/applications: without {@code all}, bundles at the application level that are not TinySEP's are left
     * out unless the drivers list names them, they were uploaded or they register a driver: infrastructure such as a
     * test harness's probe is not an application. With {@code all} they are listed with {@code infrastructure: true}.
     */
    List<Object> list(boolean all) {
        Map<String, ApplicationEntry> entries = list.entries();
        List<Object> out = new ArrayList<>();
        for (Bundle b : context.getBundles()) {
            if (b.getSymbolicName() != null && ApplicationInstaller.level(b) >= APP_LEVEL) {
                Map<String, Object> m = json(b, entries.remove(b.getSymbolicName()));
                boolean infrastructure = infrastructure(b.getSymbolicName(), (Boolean) m.get("listed"),
                        (Boolean) m.get("uploaded"), !((List<?>) m.get("drivers")).isEmpty());
                if (all) {
                    m.put("infrastructure", infrastructure);
                }
                if (all || !infrastructure) {
                    out.add(m);
                }
            }
        }
        for (ApplicationEntry e : entries.values()) { // listed, not installed
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("symbolicName", e.application());
            m.put("name", e.application());
            m.put("version", "");
            m.put("bundleId", null);
            m.put("state", "NOT_INSTALLED");
            m.put("location", e.location());
            m.put("uploaded", false);
            m.put("listed", true);
            m.put("enabled", e.enabled());
            m.put("listStatus", e.status());
            m.put("drivers", List.of());
            if (all) {
                m.put("infrastructure", false);
            }
            out.add(m);
        }
        out.sort((a, b) -> String.valueOf(((Map<?, ?>) a).get("symbolicName"))
                .compareToIgnoreCase(String.valueOf(((Map<?, ?>) b).get("symbolicName"))));
        return out;
    }

    /** @return whether a bundle at the application level is infrastructure rather than an application */
    static boolean infrastructure(String bsn, boolean listed, boolean uploaded, boolean hasDrivers) {
        return !listed && !uploaded && !hasDrivers && !bsn.startsWith("org.tinysep.");
    }

    /** POST /api/applications/{bsn}/enable or /disable */
    Map<String, Object> setEnabled(String bsn, boolean enabled) {
        DriversListAccess.checked(bsn);
        if (installer.bundle(bsn).isPresent()) {
            installer.changeable(installer.bundle(bsn).get());
        } else if (!list.entries().containsKey(bsn)) {
            throw ApiException.notFound("no application " + bsn + " (neither installed nor in the drivers list)");
        }
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("changes", list.setEnabled(bsn, enabled));
        return m;
    }

    /** POST /api/applications/reload */
    Map<String, Object> reload() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("changes", list.reload());
        return m;
    }

    Map<String, Object> json(Bundle b, ApplicationEntry entry) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("symbolicName", b.getSymbolicName());
        String name = b.getHeaders().get("Bundle-Name");
        m.put("name", name == null ? b.getSymbolicName() : name);
        m.put("version", b.getVersion().toString());
        m.put("bundleId", b.getBundleId());
        m.put("state", state(b.getState()));
        m.put("location", b.getLocation());
        m.put("uploaded", b.getLocation().startsWith(uploads.toUri().toString())
                || java.nio.file.Files.isRegularFile(uploads.resolve(b.getSymbolicName() + ".jar")));
        m.put("listed", entry != null);
        m.put("enabled", entry == null ? null : entry.enabled());
        m.put("listStatus", entry == null ? "" : entry.status());
        List<Object> drivers = new ArrayList<>();
        for (Driver d : platform.drivers(b)) {
            Map<String, Object> dm = new LinkedHashMap<>();
            dm.put("uid", Safely.get(d::uid, ""));
            dm.put("name", Safely.get(d::name, ""));
            dm.put("devices", Safely.get(() -> d.devices().size(), 0));
            drivers.add(dm);
        }
        m.put("drivers", drivers);
        return m;
    }

    static String state(int state) {
        return switch (state) {
            case Bundle.ACTIVE -> "ACTIVE";
            case Bundle.STARTING -> "STARTING";
            case Bundle.STOPPING -> "STOPPING";
            case Bundle.RESOLVED -> "RESOLVED";
            case Bundle.INSTALLED -> "INSTALLED";
            default -> "UNINSTALLED";
        };
    }
}

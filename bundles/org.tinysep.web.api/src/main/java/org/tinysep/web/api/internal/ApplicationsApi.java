package org.tinysep.web.api.internal;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleException;
import org.osgi.framework.startlevel.BundleStartLevel;
import org.osgi.framework.wiring.FrameworkWiring;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Driver;
import org.tinysep.device.support.AtomicFiles;

/**
 * {@code /api/applications}: the drivers list of thesis 3.4 as the console shows it. An application is a bundle at
 * start level {@value #APP_LEVEL} or above (bus radios, drivers, services), or an entry of the drivers list that is
 * not installed (e.g. disabled). Upload installs a new application or updates the installed one of the same
 * symbolic name; uninstall removes it; enable, disable and reload go through the drivers list. Platform bundles
 * (below level {@value #APP_LEVEL}) and the console's own are refused (409).
 */
final class ApplicationsApi {

    static final int APP_LEVEL = 5;
    private static final Logger LOG = LoggerFactory.getLogger(ApplicationsApi.class);

    private final BundleContext context;
    private final PlatformView platform;
    private final DriversListShell list;
    private final Path uploads;

    ApplicationsApi(BundleContext context, PlatformView platform, Path uploads) {
        this.context = context;
        this.platform = platform;
        this.list = new DriversListShell(platform);
        this.uploads = uploads;
    }

    /** GET /api/applications */
    List<Object> list() {
        Map<String, DriversListShell.Entry> entries = list.entries();
        List<Object> out = new ArrayList<>();
        for (Bundle b : context.getBundles()) {
            if (b.getSymbolicName() != null && level(b) >= APP_LEVEL) {
                out.add(json(b, entries.remove(b.getSymbolicName())));
            }
        }
        for (DriversListShell.Entry e : entries.values()) { // listed, not installed
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("symbolicName", e.application());
            m.put("name", e.application());
            m.put("version", "");
            m.put("bundleId", null);
            m.put("state", "NOT_INSTALLED");
            m.put("location", e.file());
            m.put("uploaded", false);
            m.put("listed", true);
            m.put("enabled", e.enabled());
            m.put("listStatus", e.status());
            m.put("drivers", List.of());
            out.add(m);
        }
        out.sort((a, b) -> String.valueOf(((Map<?, ?>) a).get("symbolicName"))
                .compareToIgnoreCase(String.valueOf(((Map<?, ?>) b).get("symbolicName"))));
        return out;
    }

    /** POST /api/applications with a jar: installs it, or updates the installed bundle of the same name */
    Map<String, Object> upload(JarUpload jar) {
        Optional<Bundle> existing = bundle(jar.symbolicName());
        Path file = uploads.resolve(jar.symbolicName() + ".jar");
        String location = file.toUri().toString();
        try {
            if (existing.isEmpty()) {
                AtomicFiles.write(file, jar.bytes());
                Bundle b = context.installBundle(location);
                b.adapt(BundleStartLevel.class).setStartLevel(APP_LEVEL);
                try {
                    b.start();
                } catch (BundleException e) {
                    uninstall(b);
                    Files.deleteIfExists(file);
                    throw ApiException.badRequest(jar.symbolicName() + " cannot start, so it was not kept: " + e.getMessage());
                }
                LOG.info("Web console: installed {} {} from an upload ({})", b.getSymbolicName(), b.getVersion(), file);
                return answer("installed", b, "");
            }
            Bundle b = changeable(existing.get());
            if (b.getLocation().equals(location)) {
                AtomicFiles.write(file, jar.bytes());
                b.update();
                LOG.info("Web console: updated {} to {} ({})", b.getSymbolicName(), b.getVersion(), file);
                return answer("updated", b, "");
            }
            b.update(new ByteArrayInputStream(jar.bytes()));
            LOG.info("Web console: updated {} to {} from an upload (until restart; listed file {})", b.getSymbolicName(),
                    b.getVersion(), b.getLocation());
            return answer("updated", b, "This update lasts until the platform restarts: the drivers list then loads "
                    + b.getLocation() + " again. To keep it, replace that file, or uninstall the application here and "
                    + "upload it again.");
        } catch (BundleException e) {
            throw ApiException.badRequest(jar.symbolicName() + " could not be installed or updated: " + e.getMessage());
        } catch (IOException e) {
            throw new ApiException(500, "could not keep the uploaded jar in " + file + ": " + e.getMessage());
        }
    }

    /** DELETE /api/applications/{bsn} */
    Map<String, Object> remove(String bsn) {
        Bundle b = changeable(bundle(DriversListShell.checked(bsn))
                .orElseThrow(() -> ApiException.notFound("no installed application " + bsn)));
        String location = b.getLocation();
        uninstall(b);
        try {
            if (location.equals(uploads.resolve(bsn + ".jar").toUri().toString())) {
                Files.deleteIfExists(uploads.resolve(bsn + ".jar"));
            }
        } catch (IOException e) {
            LOG.warn("Web console: could not delete the uploaded jar of {}: {}", bsn, e.getMessage());
        }
        LOG.info("Web console: uninstalled {}", bsn);
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("uninstalled", bsn);
        return m;
    }

    /** POST /api/applications/{bsn}/enable or /disable */
    Map<String, Object> setEnabled(String bsn, boolean enabled) {
        DriversListShell.checked(bsn);
        if (bundle(bsn).isPresent()) {
            changeable(bundle(bsn).get());
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

    private Bundle changeable(Bundle b) {
        if (level(b) < APP_LEVEL) {
            throw new ApiException(409, b.getSymbolicName() + " is a platform bundle (start level " + level(b)
                    + "): the console changes applications only");
        }
        if (b.getSymbolicName().startsWith("org.tinysep.web.")) {
            throw new ApiException(409, b.getSymbolicName() + " is the web console itself: change it from the shell");
        }
        return b;
    }

    private void uninstall(Bundle b) {
        try {
            b.uninstall();
        } catch (BundleException e) {
            throw ApiException.badRequest(b.getSymbolicName() + " could not be uninstalled: " + e.getMessage());
        }
        context.getBundle(0).adapt(FrameworkWiring.class).refreshBundles(List.of(b));
    }

    private Optional<Bundle> bundle(String bsn) {
        for (Bundle b : context.getBundles()) {
            if (bsn.equals(b.getSymbolicName())) {
                return Optional.of(b);
            }
        }
        return Optional.empty();
    }

    private static int level(Bundle b) {
        BundleStartLevel l = b.adapt(BundleStartLevel.class);
        return l == null ? 0 : l.getStartLevel();
    }

    private Map<String, Object> answer(String action, Bundle b, String note) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("action", action);
        m.put("application", json(b, null));
        m.put("note", note);
        return m;
    }

    private Map<String, Object> json(Bundle b, DriversListShell.Entry entry) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("symbolicName", b.getSymbolicName());
        String name = b.getHeaders().get("Bundle-Name");
        m.put("name", name == null ? b.getSymbolicName() : name);
        m.put("version", b.getVersion().toString());
        m.put("bundleId", b.getBundleId());
        m.put("state", state(b.getState()));
        m.put("location", b.getLocation());
        m.put("uploaded", b.getLocation().startsWith(uploads.toUri().toString()));
        m.put("listed", entry != null);
        m.put("enabled", entry == null ? null : entry.enabled());
        m.put("listStatus", entry == null ? "" : entry.status());
        List<Object> drivers = new ArrayList<>();
        for (Driver d : platform.drivers(b)) {
            Map<String, Object> dm = new LinkedHashMap<>();
            dm.put("uid", Safe.get(d::uid, ""));
            dm.put("name", Safe.get(d::name, ""));
            dm.put("devices", Safe.get(() -> d.devices().size(), 0));
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

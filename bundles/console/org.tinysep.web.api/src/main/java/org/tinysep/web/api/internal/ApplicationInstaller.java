package org.tinysep.web.api.internal;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.BiFunction;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleException;
import org.osgi.framework.startlevel.BundleStartLevel;
import org.osgi.framework.wiring.FrameworkWiring;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.drivers.ApplicationEntry;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * Installs, updates and uninstalls applications for {@link ApplicationsApi}: an upload is kept as
 * {@code <uploads>/<symbolic name>.jar} (written atomically) and installed from there at start level
 * {@value ApplicationsApi#APP_LEVEL}; a new bundle that cannot start is uninstalled again. Only bundles at that level
 * or above, and not the console's own, may be changed (else 409).
 */
final class ApplicationInstaller {

    private static final Logger LOG = LoggerFactory.getLogger(ApplicationInstaller.class);

    private final BundleContext context;
    private final Path uploads;
    private final BiFunction<Bundle, ApplicationEntry, Map<String, Object>> json;
    private final DriversListAccess list;

    ApplicationInstaller(BundleContext context, Path uploads, DriversListAccess list,
            BiFunction<Bundle, ApplicationEntry, Map<String, Object>> json) {
        this.context = context;
        this.uploads = uploads;
        this.list = list;
        this.json = json;
    }

    /** The applications that watch the person: an upload does not replace them by default. */
    static final java.util.Set<String> WATCHING = java.util.Set.of("org.tinysep.inactivity", "org.tinysep.flatoccupancy",
            "org.tinysep.alerts", "org.tinysep.sensorhealth", "org.tinysep.mailmanager");

    /**
     * @return why an upload of {@code bsn} is refused: replacing an installed watching application needs
     *         {@code replaceWatching=true}; empty when it may go ahead
     */
    static Optional<String> refusal(String bsn, boolean installed, boolean replaceWatching) {
        if (!installed || replaceWatching || !WATCHING.contains(bsn)) {
            return Optional.empty();
        }
        return Optional.of(bsn + " watches the person: an upload would replace its code with a jar nobody has "
                + "checked (uploads are not signature-checked), and the caregivers are told that monitoring was "
                + "reduced. If you mean it, upload again with replaceWatching=true (docs/security.md)");
    }

    /** POST /api/applications with a jar: installs it, or updates the installed bundle of the same name */
    Map<String, Object> upload(JarUpload jar, boolean replaceWatching) {
        Optional<Bundle> existing = bundle(jar.symbolicName());
        Optional<String> refused = refusal(jar.symbolicName(), existing.isPresent(), replaceWatching);
        if (refused.isPresent()) {
            throw new ApiException(409, refused.get());
        }
        Path file = uploads.resolve(jar.symbolicName() + ".jar");
        String location = file.toUri().toString();
        try {
            if (existing.isEmpty()) {
                AtomicFiles.write(file, jar.bytes());
                Bundle b = context.installBundle(location);
                b.adapt(BundleStartLevel.class).setStartLevel(ApplicationsApi.APP_LEVEL);
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
            // installed from elsewhere (e.g. bundles/5-apps): update the running bundle, keep the jar, and have the
            // drivers list load the kept jar from the next start on
            AtomicFiles.write(file, jar.bytes());
            b.update(new ByteArrayInputStream(jar.bytes()));
            try {
                list.use(b.getSymbolicName(), file);
            } catch (ApiException e) {
                LOG.warn("Web console: updated {} to {} from an upload, until restart only: {}", b.getSymbolicName(),
                        b.getVersion(), e.getMessage());
                return answer("updated", b, "This update lasts until the platform restarts, because the drivers list "
                        + "could not be told to keep it (" + e.getMessage() + "); it then loads " + b.getLocation()
                        + " again.");
            }
            LOG.info("Web console: updated {} to {} from an upload, kept in {} (the drivers list loads it from the next"
                    + " start on)", b.getSymbolicName(), b.getVersion(), file);
            return answer("updated", b, "Kept: from the next start on the platform loads this upload (" + file
                    + ") instead of " + b.getLocation() + ". When a later version of the platform brings a newer "
                    + b.getSymbolicName() + " than this one, the newer one is used.");
        } catch (BundleException e) {
            throw ApiException.badRequest(jar.symbolicName() + " could not be installed or updated: " + e.getMessage());
        } catch (IOException e) {
            throw new ApiException(500, "could not keep the uploaded jar in " + file + ": " + e.getMessage());
        }
    }

    /** DELETE /api/applications/{bsn} */
    Map<String, Object> remove(String bsn) {
        Bundle b = changeable(bundle(DriversListAccess.checked(bsn))
                .orElseThrow(() -> ApiException.notFound("no installed application " + bsn)));
        uninstall(b);
        try {
            Files.deleteIfExists(uploads.resolve(bsn + ".jar")); // also an update of a bundle from elsewhere
        } catch (IOException e) {
            LOG.warn("Web console: could not delete the uploaded jar of {}: {}", bsn, e.getMessage());
        }
        LOG.info("Web console: uninstalled {}", bsn);
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("uninstalled", bsn);
        return m;
    }

    Bundle changeable(Bundle b) {
        if (level(b) < ApplicationsApi.APP_LEVEL) {
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

    Optional<Bundle> bundle(String bsn) {
        for (Bundle b : context.getBundles()) {
            if (bsn.equals(b.getSymbolicName())) {
                return Optional.of(b);
            }
        }
        return Optional.empty();
    }

    static int level(Bundle b) {
        BundleStartLevel l = b.adapt(BundleStartLevel.class);
        return l == null ? 0 : l.getStartLevel();
    }

    private Map<String, Object> answer(String action, Bundle b, String note) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("action", action);
        m.put("application", json.apply(b, null));
        m.put("note", note);
        return m;
    }

}

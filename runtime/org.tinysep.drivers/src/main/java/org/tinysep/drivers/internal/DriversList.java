package org.tinysep.drivers.internal;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.BundleEvent;
import org.osgi.framework.BundleListener;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Deactivate;
import org.osgi.service.component.annotations.Reference;
import org.osgi.service.metatype.annotations.Designate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.drivers.ApplicationEntry;
import org.tinysep.api.drivers.DriversListService;
import org.tinysep.api.log.EventLog;
import org.tinysep.device.support.files.StateFolder;

/**
 * The drivers list component (thesis 3.4): loads {@code drivers.xml} (seeding it from the applications folder on
 * first start), installs and starts its enabled entries, keeps every entry's STATUS up to date in the file, follows
 * shell installs and uninstalls, and reconciles on request. All list changes hold this object's lock.
 */
@Component(service = {DriversList.class, DriversListService.class}, immediate = true, configurationPid = DriversList.PID,
        // not used here: an ordering guarantee. Applications restore their devices from the system backup when they
        // activate (docs/backup.md), so they may start only once the device manager's store is registered.
        reference = @Reference(name = "backupStore", service = BackupStore.class))
@Designate(ocd = DriversConfig.class)
public final class DriversList implements BundleListener, DriversListService {

    static final String PID = "org.tinysep.drivers";
    private static final Logger LOG = LoggerFactory.getLogger(DriversList.class);

    private final BundleContext context;
    private final DriversConfig config;
    private final Locations locations;
    private final DriversFile file;
    private final OsgiBundles bundles;
    private final Report report;
    private final Reconciler reconciler;
    private final Path deployFolder;
    private final CoalescingSaver saver = new CoalescingSaver(this::saveNow, 100);
    private List<DriverEntry> entries = List.of();

    @Activate
    public DriversList(BundleContext context, DriversConfig config, @Reference(name = "eventLog") EventLog events) {
        this.context = context;
        this.config = config;
        this.report = new Report(events);
        String home = context.getProperty(StateFolder.HOME);
        Path homePath = home == null || home.isBlank() ? null : Path.of(home.strip());
        this.locations = new Locations(homePath);
        this.file = new DriversFile(StateFolder.resolve(config.file(), context, "drivers.xml")
                .orElseGet(() -> context.getDataFile("drivers.xml").toPath()), new DriversCodec());
        this.bundles = new OsgiBundles(context);
        this.reconciler = new Reconciler(bundles, locations, config.startLevel());
        this.deployFolder = folder(config.deployFolder(), homePath, "deploy");
        context.addFrameworkListener(bundles);
        synchronized (this) {
            List<DriverEntry> initial = Seed.startList(file, folder(config.seedFolder(), homePath, "bundles/5-apps"),
                    locations, report);
            Reconciler.Result r = reconciler.apply(initial);
            entries = r.entries();
            LOG.info("Drivers list {}: {} entries; {}", file.path(), entries.size(), Report.summary(r.changes()));
            LOG.debug("Drivers list changes: {}", r.changes());
            r.changes().stream().filter(c -> c.startsWith("cannot ") || c.startsWith("missing ")).forEach(report::problem);
            save();
        }
        context.addBundleListener(this);
    }

    @Deactivate
    void deactivate() {
        context.removeBundleListener(this);
        context.removeFrameworkListener(bundles);
        saver.close();
    }

    /** @return the entries with their live status */
    synchronized List<DriverEntry> entries() {
        return entries.stream().map(e -> e.withStatus(reconciler.status(e))).toList();
    }

    /** @return the list file */
    Path path() {
        return file.path();
    }

    @Override
    public String file() {
        return file.path().toString();
    }

    @Override
    public List<ApplicationEntry> applications() {
        return entries().stream()
                .map(e -> new ApplicationEntry(e.key(), e.symbolicName(), e.location(), e.enabled(), e.status()))
                .toList();
    }

    /**
     * Re-reads the file and reconciles. A malformed file is moved aside and the previous list stays in force (and
     * is written back).
     *
     * @return one line per change, or why nothing changed
     */
    @Override
    public synchronized List<String> reload() {
        List<DriverEntry> wanted;
        try {
            wanted = file.exists() ? file.read(Instant.now()) : entries;
        } catch (MalformedDriversException | IOException e) {
            String problem = e.getMessage();
            report.problem("not reloaded: " + problem + "; keeping the previous list (" + entries.size() + " entries)");
            save();
            throw new IllegalStateException(problem + "; kept the previous list (" + entries.size() + " entries)");
        }
        Reconciler.Result r = reconciler.apply(wanted);
        entries = r.entries();
        save();
        report.changes(r.changes());
        return r.changes();
    }

    /** Sets {@code ENABLED} of the entry named {@code bsn} and applies it at once. @return the changes */
    @Override
    public synchronized List<String> setEnabled(String bsn, boolean enabled) {
        List<DriverEntry> wanted = new ArrayList<>();
        boolean found = false;
        for (DriverEntry e : entries) {
            boolean match = e.symbolicName().equals(bsn) || e.location().equals(bsn);
            found |= match;
            wanted.add(match ? e.withEnabled(enabled) : e);
        }
        if (!found) {
            throw new IllegalArgumentException("no entry " + bsn + " in the drivers list (see tinysep:drivers)");
        }
        Reconciler.Result r = reconciler.apply(wanted);
        entries = r.entries();
        save();
        report.changes(r.changes());
        return r.changes().isEmpty() ? List.of(bsn + " is already " + (enabled ? "enabled" : "disabled"))
                : r.changes();
    }

    /**
     * Points the entry named {@code bsn} at another file (e.g. the web console's copy of an uploaded update, which
     * the running bundle already is), or adds an enabled entry for it; nothing is installed or restarted now: from
     * the next start on the platform loads that file. The file must be a bundle of that symbolic name.
     *
     * @return what changed, in words
     */
    @Override
    public synchronized String use(String bsn, String file) {
        Optional<Path> path = locations.file(file).filter(Files::isRegularFile);
        if (path.isEmpty()) {
            throw new IllegalArgumentException("no file " + file + ": give the path of a bundle jar");
        }
        String name = Seed.symbolicName(path.get());
        if (!bsn.equals(name)) {
            throw new IllegalArgumentException(file + " is " + (name == null ? "not a bundle" : "the bundle " + name)
                    + ", not " + bsn);
        }
        String filePath = locations.filePath(path.get().toUri().toString());
        List<DriverEntry> next = new ArrayList<>();
        String before = null;
        for (DriverEntry e : entries) {
            if (e.symbolicName().equals(bsn)) {
                before = e.location();
                next.add(new DriverEntry(filePath, bsn, e.enabled(), e.status()));
            } else {
                next.add(e);
            }
        }
        if (before == null) {
            next.add(new DriverEntry(filePath, bsn, true, ""));
            long id = bundles.find(bsn, path.get().toUri().toString());
            if (id >= 0) {
                reconciler.adopt(bsn, id);
            }
        }
        entries = List.copyOf(next);
        save();
        String change = bsn + " is loaded from " + filePath + " from the next start on"
                + (before == null ? " (added to the list)" : " (was " + before + ")");
        report.change(change);
        return change;
    }

    @Override
    public void bundleChanged(BundleEvent event) {
        if (context.getBundle(0).getState() == Bundle.STOPPING) {
            return; // shutting down: the list keeps what was running
        }
        Bundle b = event.getBundle();
        switch (event.getType()) {
            case BundleEvent.INSTALLED -> shellInstalled(b);
            case BundleEvent.UNINSTALLED -> shellUninstalled(b);
            default -> {
            }
        }
        if (reconciler.manages(b.getBundleId()) || event.getType() == BundleEvent.UNINSTALLED) {
            saver.request();
        }
    }

    private synchronized void shellInstalled(Bundle b) {
        String location = b.getLocation();
        if (!config.trackShellInstalls() || reconciler.manages(b.getBundleId()) || !location.startsWith("file:")
                || locations.isUnder(location, deployFolder) || b.getSymbolicName() == null
                || entries.stream().anyMatch(e -> e.symbolicName().equals(b.getSymbolicName()))) {
            return;
        }
        DriverEntry added = new DriverEntry(locations.filePath(location), b.getSymbolicName(), true, "");
        List<DriverEntry> next = new ArrayList<>(entries);
        next.add(added);
        entries = List.copyOf(next);
        reconciler.adopt(added.key(), b.getBundleId());
        report.change("added " + added.key() + " (" + location + "), installed from outside the deploy folder");
    }

    private synchronized void shellUninstalled(Bundle b) {
        Optional<String> key = reconciler.uninstalled(b.getBundleId());
        if (key.isPresent()) {
            entries = entries.stream().filter(e -> !e.key().equals(key.get())).toList();
            report.change("removed " + key.get() + ", uninstalled from the shell");
        }
    }

    private synchronized void saveNow() {
        save();
    }

    /** Writes the list with live statuses; a failure is logged, the list in memory stays. */
    private void save() {
        try {
            file.save(entries());
        } catch (IOException | RuntimeException e) {
            report.problem("cannot write " + file.path() + ": " + e.getMessage());
        }
    }

    private static Path folder(String configured, Path home, String relative) {
        if (configured != null && !configured.isBlank()) {
            return Path.of(configured.strip()).toAbsolutePath();
        }
        return home == null ? null : home.resolve(relative);
    }
}

package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Driver;
import org.tinysep.device.support.AtomicFiles;
import org.tinysep.device.support.StateFolder;

/**
 * {@code tinysep:backup [file]} writes the whole configuration as one zip archive; {@code tinysep:restore <file>}
 * validates an archive completely, then stops the application bundles that run drivers (transiently), replaces
 * the backup folder (the old one is kept as {@code backup.before-restore-<timestamp>}), writes house.xml,
 * drivers.xml and etc/*.cfg, reloads the store and starts those bundles again, which re-create their devices from
 * the restored backups (docs/backup.md).
 */
@Component(service = BackupCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=backup",
    "osgi.command.function=restore"
})
public final class BackupCommands {

    private static final Logger LOG = LoggerFactory.getLogger(BackupCommands.class);
    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd'T'HHmmss'Z'")
            .withZone(ZoneOffset.UTC);

    private final BundleContext context;
    private final BackupStoreService store;
    private final BackupCodec codec;

    @Activate
    public BackupCommands(BundleContext context, @Reference(name = "store") BackupStoreService store) {
        this.context = context;
        this.store = store;
        this.codec = store.codec();
    }

    /** {@code backup}: the archive goes to the state folder as {@code tinysep-backup-<UTC time>.zip}. */
    public String backup() {
        return backup(var().resolve("tinysep-backup-" + STAMP.format(Instant.now()) + ".zip").toString());
    }

    /** {@code backup <file>}: writes the archive to that file (replacing it atomically). */
    public String backup(String file) {
        Path target = Path.of(file).toAbsolutePath();
        if (!store.flush(java.time.Duration.ofSeconds(10))) {
            throw new IllegalStateException("the backup store did not finish writing within 10 s; try again");
        }
        try {
            int n = BackupArchive.write(target, store.root(), var(), etc());
            return "wrote " + n + " files to " + target;
        } catch (IOException e) {
            throw new IllegalStateException("cannot write " + target + ": " + e.getMessage());
        }
    }

    /** {@code restore <file>}: validates, then imports and re-applies the archive. */
    public String restore(String file) {
        Path archive = Path.of(file).toAbsolutePath();
        Map<String, byte[]> content = BackupArchive.read(archive, codec); // throws before anything changes
        List<Bundle> apps = driverBundles();
        List<String> problems = new ArrayList<>();
        for (Bundle b : apps) {
            try {
                b.stop(Bundle.STOP_TRANSIENT);
            } catch (Exception e) {
                problems.add("stop " + b.getSymbolicName() + ": " + e.getMessage());
            }
        }
        String kept;
        try {
            store.flush(java.time.Duration.ofSeconds(10));
            kept = replaceFolder(content);
            store.reload();
            for (Map.Entry<String, byte[]> e : content.entrySet()) {
                if (e.getKey().equals("house.xml") || e.getKey().equals("drivers.xml")) {
                    AtomicFiles.write(var().resolve(e.getKey()), e.getValue());
                } else if (e.getKey().startsWith("etc/") && etc() != null) {
                    AtomicFiles.write(etc().resolve(e.getKey().substring(4)), e.getValue());
                }
            }
        } catch (IOException e) {
            problems.add("import: " + e.getMessage());
            kept = "?";
        } finally {
            for (Bundle b : apps) {
                try {
                    b.start(Bundle.START_TRANSIENT);
                } catch (Exception e) {
                    problems.add("start " + b.getSymbolicName() + ": " + e.getMessage());
                }
            }
        }
        LOG.info("Restored {} ({} files); previous backup folder kept as {}", archive, content.size(), kept);
        return "restored " + content.size() + " files from " + archive + "; restarted " + apps.size()
                + " application bundles; previous backup folder kept as " + kept
                + (problems.isEmpty() ? "" : "; problems: " + String.join("; ", problems));
    }

    private String replaceFolder(Map<String, byte[]> content) throws IOException {
        Path root = store.root();
        Path staging = root.resolveSibling(root.getFileName() + ".restoring");
        deleteTree(staging);
        for (Map.Entry<String, byte[]> e : content.entrySet()) {
            if (e.getKey().startsWith("backup/")) {
                AtomicFiles.write(staging.resolve(e.getKey().substring("backup/".length())), e.getValue());
            }
        }
        Path old = root.resolveSibling(root.getFileName() + ".before-restore-" + STAMP.format(Instant.now()));
        if (Files.exists(root)) {
            AtomicFiles.move(root, old);
        }
        AtomicFiles.move(staging, root);
        return old.getFileName().toString();
    }

    private static void deleteTree(Path dir) throws IOException {
        if (Files.exists(dir)) {
            try (Stream<Path> walk = Files.walk(dir)) {
                for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) {
                    Files.delete(p);
                }
            }
        }
    }

    /** @return the bundles (other than the device manager) that registered a Driver service */
    private List<Bundle> driverBundles() {
        Set<Bundle> out = new LinkedHashSet<>();
        try {
            ServiceReference<?>[] refs = context.getServiceReferences(Driver.class.getName(), null);
            for (ServiceReference<?> r : refs == null ? new ServiceReference<?>[0] : refs) {
                Bundle b = r.getBundle();
                if (b != null && b.getBundleId() != 0 && b.getBundleId() != context.getBundle().getBundleId()) {
                    out.add(b);
                }
            }
        } catch (org.osgi.framework.InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        return new ArrayList<>(out);
    }

    private Path var() {
        return store.root().getParent();
    }

    private Path etc() {
        String home = context.getProperty(StateFolder.HOME);
        return home == null || home.isBlank() ? null : Path.of(home.strip(), "etc");
    }
}

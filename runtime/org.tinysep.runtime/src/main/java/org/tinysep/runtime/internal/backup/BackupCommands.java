package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.apache.felix.service.command.Descriptor;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.InvalidSyntaxException;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.osgi.service.component.annotations.Activate;
import org.osgi.service.component.annotations.Component;
import org.osgi.service.component.annotations.Reference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Driver;
import org.tinysep.device.support.files.StateFolder;
import org.tinysep.runtime.internal.shell.Usage;

/**
 * {@code tinysep:backup [--with-secrets] [file]} writes the configuration as one signed zip archive;
 * {@code tinysep:restore [--force] <file>} validates an archive completely and replaces the state with it, keeping a
 * copy of what it replaces; {@code tinysep:restore --undo} brings that copy back ({@link Restorer},
 * docs/backup.md).
 */
@Component(service = BackupCommands.class, property = {
    "osgi.command.scope=tinysep",
    "osgi.command.function=backup",
    "osgi.command.function=restore"
})
public final class BackupCommands {

    static final String WITH_SECRETS = "--with-secrets";
    static final String FORCE = "--force";
    static final String UNDO = "--undo";
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
    @Descriptor("writes the system backup (settings, rooms, drivers list, TinySEP's etc/ files; no passwords) to a signed"
            + " zip archive tinysep-backup-<UTC time>.zip in the state folder")
    public String backup() {
        return write(null, false);
    }

    /** {@code backup <file>} or {@code backup --with-secrets}. */
    @Descriptor("writes the system backup to the given file, or with --with-secrets also the state folder's secrets/")
    public String backup(@Descriptor("the archive file to write, or --with-secrets") String fileOrFlag) {
        return WITH_SECRETS.equals(fileOrFlag) ? write(null, true) : write(option(fileOrFlag), false);
    }

    /** {@code backup --with-secrets <file>}. */
    @Descriptor("writes the system backup with the state folder's secrets/ (not the signing key) to the given file")
    public String backup(@Descriptor("--with-secrets") String flag, @Descriptor("the archive file to write") String file) {
        if (!WITH_SECRETS.equals(flag)) {
            throw new IllegalArgumentException("usage: tinysep:backup [--with-secrets] [file]");
        }
        return write(option(file), true);
    }

    /** {@code restore <file>}, or {@code restore --undo}. */
    @Descriptor("restores a signed backup archive after checking every file in it (only TinySEP's own settings; the"
            + " clock mode is kept); a copy of the state it replaces is kept, and --undo brings that copy back")
    public String restore(@Descriptor("the archive file, or --undo") String fileOrFlag) throws IOException {
        if (UNDO.equals(fileOrFlag)) {
            String out = restorer().undo();
            LOG.info("{}", out);
            return out;
        }
        return restore(option(fileOrFlag), false);
    }

    /** {@code restore --force <file>}: also an unsigned or foreign archive (still fully validated). */
    @Descriptor("restores an unsigned or foreign archive as well (every other check still applies)")
    public String restore(@Descriptor("--force") String flag, @Descriptor("the archive file") String file)
            throws IOException {
        if (!FORCE.equals(flag)) {
            throw new IllegalArgumentException("usage: tinysep:restore [--force] <file> | tinysep:restore --undo");
        }
        return restore(option(file), true);
    }

    @Descriptor("with no argument: prints the usage")
    public String restore() {
        throw new IllegalArgumentException("missing arguments; usage: tinysep:restore [--force] <file> | tinysep:restore"
                + " --undo (help tinysep:restore explains them)");
    }

    /** {@code backup} or {@code restore} with more arguments than any form takes: the usage. */
    @Descriptor("with too many arguments: prints the usage")
    public String backup(@Descriptor("anything else") String... wrong) {
        throw Usage.of("backup [--with-secrets] [file]", wrong);
    }

    @Descriptor("with too many arguments: prints the usage")
    public String restore(@Descriptor("anything else") String... wrong) {
        throw Usage.of("restore [--force] <file> | tinysep:restore --undo", wrong);
    }

    private String restore(String file, boolean force) throws IOException {
        String out = restorer().restore(Path.of(file).toAbsolutePath(), force);
        LOG.info("{}", out);
        return out;
    }

    private String write(String file, boolean withSecrets) {
        StateFiles files = files();
        Path target = file == null ? files.var().resolve("tinysep-backup-" + STAMP.format(Instant.now()) + ".zip")
                : Path.of(file).toAbsolutePath();
        store.settleJournal(); // the last seen times of the last stop into the files the archive holds
        if (!store.flush(Duration.ofSeconds(10))) {
            throw new IllegalStateException("the backup store did not finish writing within 10 s; try again");
        }
        try {
            int n = BackupArchive.write(target, files.collect(true, withSecrets),
                    ArchiveSignature.loadOrCreate(files.keyFile()));
            return "wrote " + n + " files to " + target + (withSecrets ? " (with the secrets folder: keep it safe)"
                    : " (signed; passwords and the secrets folder left out)");
        } catch (IOException e) {
            throw new IllegalStateException("cannot write " + target + ": " + e.getMessage());
        }
    }

    private static String option(String file) {
        if (file.startsWith("--")) {
            throw new IllegalArgumentException("unknown option " + file
                    + "; usage: tinysep:backup [--with-secrets] [file], tinysep:restore [--force] <file> | --undo");
        }
        return file;
    }

    private Restorer restorer() {
        return new Restorer(files(), codec, store.limits(), new Restorer.Platform() {
            private final List<Bundle> apps = driverBundles();

            @Override
            public int stopApplications(List<String> problems) {
                for (Bundle b : apps) {
                    try {
                        b.stop(Bundle.STOP_TRANSIENT);
                    } catch (Exception e) {
                        problems.add("stop " + b.getSymbolicName() + ": " + e.getMessage());
                    }
                }
                return apps.size();
            }

            @Override
            public void flushStore() {
                store.settleJournal(); // the undo copy holds the files
                store.flush(Duration.ofSeconds(10));
            }

            @Override
            public void reloadStore() {
                store.reload();
            }

            @Override
            public void settingsChanged(Path archive, List<String> changes) {
                String message = "Monitoring reduced: a restore of " + archive.getFileName() + " changed "
                        + changes.size() + " setting(s) (limits, recipients or addresses may be among them; old → new): "
                        + String.join("; ", changes) + ". If nobody meant this, tinysep:restore --undo brings the "
                        + "settings before back";
                LOG.warn("{}", message);
                ServiceReference<EventLog> ref = context.getServiceReference(EventLog.class);
                EventLog log = ref == null ? null : context.getService(ref);
                if (log != null) {
                    try {
                        log.record(EventKind.PROBLEM, "backup", message);
                    } finally {
                        context.ungetService(ref);
                    }
                }
            }

            @Override
            public void startApplications(List<String> problems) {
                for (Bundle b : apps) {
                    try {
                        b.start(Bundle.START_TRANSIENT);
                    } catch (Exception e) {
                        problems.add("start " + b.getSymbolicName() + ": " + e.getMessage());
                    }
                }
            }
        });
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
        } catch (InvalidSyntaxException e) {
            throw new IllegalStateException(e);
        }
        return new ArrayList<>(out);
    }

    private StateFiles files() {
        String home = context.getProperty(StateFolder.HOME);
        return new StateFiles(store.root(), store.root().getParent(),
                home == null || home.isBlank() ? null : Path.of(home.strip(), "etc"));
    }
}

package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.TreeMap;
import java.util.Optional;
import java.util.stream.Stream;
import javax.crypto.Mac;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * {@code tinysep:restore} without OSGi (docs/backup.md § Restore): all or nothing. The archive is streamed into a
 * staging folder within the limits, its signature checked and every file validated; any problem refuses it and
 * nothing changes. Then the applications are stopped, a complete copy of the current state is kept
 * ({@code before-restore/previous-<time>.zip}, signed), the backup folder swapped and the other files replaced
 * atomically (on a failure the copy is put back), and the applications started again. {@link #undo} restores the
 * newest copy the same way.
 */
final class Restorer {

    /** What the restore needs from the running platform. */
    interface Platform {
        /** Stops the applications that run drivers; @return how many */
        int stopApplications(List<String> problems);

        /** Writes queued backups, then (after the swap) reads the backup folder again. */
        void flushStore();

        void reloadStore();

        void startApplications(List<String> problems);

        /** A restore changed these settings: the caregivers are told. */
        default void settingsChanged(Path archive, List<String> changes) {
        }
    }

    /** One restore at a time (two shell sessions share the staging folder and the applications). */
    private static final Object RUNNING = new Object();

    private final StateFiles files;
    private final BackupCodec codec;
    private final ArchiveUnpacker.Limits limits;
    private final Platform platform;

    Restorer(StateFiles files, BackupCodec codec, ArchiveUnpacker.Limits limits, Platform platform) {
        this.files = files;
        this.codec = codec;
        this.limits = limits;
        this.platform = platform;
    }

    /** @throws IllegalArgumentException when the archive is refused (nothing changed), saying every reason */
    String restore(Path archive, boolean force) throws IOException {
        return run(archive, force, false);
    }

    /** Brings back the state the last restore (or undo) replaced. */
    String undo() throws IOException {
        Path copy = new UndoCopies(files).newest().orElseThrow(() -> new IllegalStateException(
                "nothing to undo: no restore has kept a copy in " + files.undoFolder()));
        return run(copy, false, true);
    }

    private String run(Path archive, boolean force, boolean undo) throws IOException {
        synchronized (RUNNING) {
            return runAlone(archive, force, undo);
        }
    }

    private String runAlone(Path archive, boolean force, boolean undo) throws IOException {
        Path staging = files.var().resolve("restore.staging");
        deleteTree(staging);
        try {
            Optional<ArchiveSignature> key = ArchiveSignature.load(files.keyFile());
            Mac mac = key.map(ArchiveSignature::newMac).orElse(null);
            ArchiveUnpacker.Unpacked staged;
            try {
                staged = ArchiveUnpacker.unpack(archive, staging, limits, mac);
            } catch (ArchiveUnpacker.TooLarge e) {
                throw refused(archive, List.of(e.getMessage()));
            } catch (IOException e) {
                throw refused(archive, List.of("not a readable zip archive: " + e.getMessage()));
            }
            List<String> problems = new ArrayList<>(staged.problems());
            problems.addAll(ArchiveValidator.problems(staging, staged.names(), codec, !undo));
            List<String> notes = new ArrayList<>();
            String origin = key.isEmpty() ? "this installation has no backup key yet (" + files.keyFile()
                    + "), so the archive's origin cannot be checked" : key.get().check(staged.signature(), mac);
            if (origin != null && force) {
                notes.add("restored although " + origin + " (--force)");
            } else if (origin != null) {
                problems.add(origin + "; if you trust it, restore it with tinysep:restore --force <file>");
            }
            if (!problems.isEmpty()) {
                throw refused(archive, problems);
            }
            List<String> trouble = new ArrayList<>();
            List<String> changed = new ArrayList<>();
            int apps = platform.stopApplications(trouble);
            Path copy;
            try {
                platform.flushStore(); // the devices' last states are in the copy too
                copy = new UndoCopies(files).keep();
                TreeMap<String, String> settingsBefore = SettingChanges.read(files.etc());
                try {
                    swapAndApply(staging, staged.names(), undo, notes);
                    changed.addAll(SettingChanges.diff(settingsBefore, SettingChanges.read(files.etc())));
                } catch (IOException | RuntimeException e) {
                    throw new IllegalStateException("the restore failed while replacing files (" + e.getMessage()
                            + "); " + putBack(copy), e);
                }
            } finally {
                platform.startApplications(trouble);
            }
            if (!changed.isEmpty()) {
                platform.settingsChanged(archive, changed);
            }
            return (undo ? "undone: brought back " : "restored ") + staged.names().size() + " files from " + archive
                    + "; restarted " + apps + " application bundles"
                    + (trouble.isEmpty() ? "" : "; problems: " + String.join("; ", trouble))
                    + "; the state before is kept in " + files.var().relativize(copy)
                    + " (tinysep:restore --undo brings it back)"
                    + (changed.isEmpty() ? "\nno setting in etc/ changed" : "\nsettings changed (old → new), "
                    + changed.size() + ":\n  " + String.join("\n  ", changed))
                    + (notes.isEmpty() ? "" : "\n" + String.join("\n", notes));
        } finally {
            deleteTree(staging);
        }
    }

    /** Swaps the staged backup folder in, has the store read it, and writes the other staged files. */
    private void swapAndApply(Path staging, List<String> names, boolean exact, List<String> notes)
            throws IOException {
        Path root = files.backupRoot();
        Path stagedRoot = staging.resolve("backup");
        AtomicFiles.createPrivateDirectories(stagedRoot);
        Path old = root.resolveSibling(root.getFileName() + ".replaced");
        deleteTree(old);
        if (Files.exists(root)) {
            AtomicFiles.move(root, old);
        }
        AtomicFiles.move(stagedRoot, root);
        if (Files.isDirectory(old.resolve(BackupLayout.DAMAGED))) {
            AtomicFiles.move(old.resolve(BackupLayout.DAMAGED), root.resolve(BackupLayout.DAMAGED));
        }
        deleteTree(old); // its files are in the copy kept
        platform.reloadStore();
        notes.addAll(files.apply(staging, names, exact));
    }

    /** After a failed replace: the copy kept before goes back in place; @return what happened, in words */
    private String putBack(Path copy) {
        Path staging = files.var().resolve("restore.rollback");
        try {
            deleteTree(staging);
            ArchiveUnpacker.Unpacked staged = ArchiveUnpacker.unpack(copy, staging, limits, null);
            swapAndApply(staging, staged.names(), true, new ArrayList<>());
            return "the previous state was put back";
        } catch (IOException | RuntimeException e) {
            return "putting the previous state back failed too (" + e.getMessage() + "): run tinysep:restore --undo";
        } finally {
            try {
                deleteTree(staging);
            } catch (IOException ignored) {
                // left for the next restore, which deletes it first
            }
        }
    }

    private static IllegalArgumentException refused(Path archive, List<String> problems) {
        return new IllegalArgumentException(archive.getFileName() + " rejected, nothing changed: "
                + String.join("; ", problems));
    }

    static void deleteTree(Path dir) throws IOException {
        if (Files.exists(dir)) {
            try (Stream<Path> walk = Files.walk(dir)) {
                for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) {
                    Files.delete(p);
                }
            }
        }
    }
}

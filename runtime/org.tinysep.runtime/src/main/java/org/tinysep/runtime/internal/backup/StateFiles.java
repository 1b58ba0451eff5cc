package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * The state an archive carries, where it lives and how it is read and replaced (docs/backup.md): the backup
 * folder's files (not {@code damaged/}), {@code house.xml} and {@code drivers.xml} of the state folder, the
 * {@code etc/*.cfg} files TinySEP owns ({@link OwnedConfig}), and on request the secrets folder
 * ({@code ${tinysep.var}/secrets/}, never its {@code backup.key}).
 */
final class StateFiles {

    static final List<String> VAR_FILES = List.of("house.xml", "drivers.xml");

    private final Path backupRoot;
    private final Path var;
    private final Path etc;

    /** @param etc {@code ${tinysep.home}/etc}, or null when there is none (cfg files are then left out) */
    StateFiles(Path backupRoot, Path var, Path etc) {
        this.backupRoot = backupRoot;
        this.var = var;
        this.etc = etc;
    }

    /** @return {@code ${tinysep.home}/etc}, or null */
    Path etc() {
        return etc;
    }

    Path backupRoot() {
        return backupRoot;
    }

    Path var() {
        return var;
    }

    Path secrets() {
        return var.resolve("secrets");
    }

    Path keyFile() {
        return secrets().resolve(ArchiveSignature.KEY_FILE);
    }

    /** Where a restore keeps the state it replaced ({@code previous-<time>.zip}). */
    Path undoFolder() {
        return var.resolve("before-restore");
    }

    /**
     * @param forArchive true: what {@code tinysep:backup} writes (secret keys left out of cfg files); false: a
     *                   complete copy for {@code --undo}
     * @return entry name to content, in a stable order
     */
    Map<String, byte[]> collect(boolean forArchive, boolean withSecrets) throws IOException {
        Map<String, byte[]> out = new LinkedHashMap<>();
        if (Files.isDirectory(backupRoot)) {
            try (Stream<Path> walk = Files.walk(backupRoot, 2)) {
                for (Path p : walk.filter(Files::isRegularFile).filter(f -> f.getFileName().toString().endsWith(".xml"))
                        .filter(f -> !f.getParent().getFileName().toString().equals(BackupLayout.DAMAGED))
                        .filter(f -> !f.getParent().equals(backupRoot)).sorted().toList()) {
                    out.put("backup/" + backupRoot.relativize(p).toString().replace('\\', '/'), Files.readAllBytes(p));
                }
            }
        }
        for (String name : VAR_FILES) {
            if (Files.isRegularFile(var.resolve(name))) {
                out.put(name, Files.readAllBytes(var.resolve(name)));
            }
        }
        for (Path cfg : ownedCfgs()) {
            byte[] bytes = Files.readAllBytes(cfg);
            out.put("etc/" + cfg.getFileName(), forArchive ? OwnedConfig.forBackup(bytes) : bytes);
        }
        if (withSecrets && Files.isDirectory(secrets())) {
            try (Stream<Path> list = Files.list(secrets())) {
                for (Path s : list.filter(Files::isRegularFile).sorted().toList()) {
                    String n = s.getFileName().toString();
                    if (!n.equals(ArchiveSignature.KEY_FILE) && ArchiveUnpacker.NAME.matcher("secrets/" + n).matches()) {
                        out.put("secrets/" + n, Files.readAllBytes(s));
                    }
                }
            }
        }
        return out;
    }

    /**
     * Writes the staged {@code house.xml}, {@code drivers.xml}, cfg and secrets files atomically; the backup folder
     * is swapped by the caller.
     *
     * @param exact true (undo): those state files the staged copy lacks are deleted, so the state is the copy's
     * @return what the user should know (keys kept from this installation)
     */
    List<String> apply(Path staged, List<String> names, boolean exact) throws IOException {
        List<String> notes = new ArrayList<>();
        for (String name : names) {
            if (name.startsWith("backup/")) {
                continue; // the backup folder is swapped as a whole
            }
            byte[] bytes = Files.readAllBytes(staged.resolve(name));
            if (VAR_FILES.contains(name)) {
                writeIfChanged(var.resolve(name), bytes);
            } else if (name.startsWith("etc/") && etc != null) {
                Path target = etc.resolve(name.substring(4));
                OwnedConfig.Merged m = OwnedConfig.forRestore(target.getFileName().toString(), bytes,
                        Files.isRegularFile(target) ? Files.readAllBytes(target) : null);
                writeIfChanged(target, m.content());
                notes.addAll(m.notes());
            } else if (name.startsWith("secrets/")) {
                writeIfChanged(secrets().resolve(name.substring(8)), bytes);
            }
        }
        if (exact) {
            for (String name : VAR_FILES) {
                if (!names.contains(name)) {
                    AtomicFiles.delete(var.resolve(name));
                }
            }
            for (Path cfg : ownedCfgs()) {
                if (!names.contains("etc/" + cfg.getFileName())) {
                    AtomicFiles.delete(cfg);
                }
            }
            for (String secret : collect(false, true).keySet()) {
                if (secret.startsWith("secrets/") && !names.contains(secret)) {
                    AtomicFiles.delete(secrets().resolve(secret.substring(8)));
                }
            }
        }
        return notes;
    }

    /** Files already as wanted are not touched (FileInstall sees no change; a put-back writes only what moved). */
    private static void writeIfChanged(Path target, byte[] bytes) throws IOException {
        if (!Files.isRegularFile(target) || !java.util.Arrays.equals(Files.readAllBytes(target), bytes)) {
            AtomicFiles.write(target, bytes);
        }
    }

    private List<Path> ownedCfgs() throws IOException {
        if (etc == null || !Files.isDirectory(etc)) {
            return List.of();
        }
        try (Stream<Path> list = Files.list(etc)) {
            return list.filter(Files::isRegularFile).filter(p -> OwnedConfig.owned(p.getFileName().toString()))
                    .sorted().toList();
        }
    }
}

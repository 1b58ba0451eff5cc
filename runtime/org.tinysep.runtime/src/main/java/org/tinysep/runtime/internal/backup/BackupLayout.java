package org.tinysep.runtime.internal.backup;

import java.nio.file.Path;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.backup.ComponentKind;

/**
 * Where backup files live (docs/backup.md): {@code <root>/<driver name>/<device type>-<uid>.xml} for a device,
 * {@code <root>/<driver name>/driver-<uid>.xml} for a driver, damaged files moved to
 * {@code <root>/damaged/<driver name>_<file name>.<UTC timestamp>}. Names keep letters, digits, {@code . _ -}.
 */
final class BackupLayout {

    static final String DAMAGED = "damaged";
    static final String SUFFIX = ".xml";
    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd'T'HHmmss.SSS'Z'")
            .withZone(ZoneOffset.UTC);

    private final Path root;

    BackupLayout(Path root) {
        this.root = root.toAbsolutePath().normalize();
    }

    Path root() {
        return root;
    }

    Path damagedFolder() {
        return root.resolve(DAMAGED);
    }

    Path fileOf(ComponentBackup b) {
        String folder = safe(b.driverName().isBlank() ? "unknown-driver" : b.driverName());
        String prefix = b.kind() == ComponentKind.DRIVER ? "driver" : safe(b.type().isBlank() ? "device" : b.type());
        return root.resolve(folder).resolve(prefix + "-" + safe(b.uid()) + SUFFIX);
    }

    /** @return where a damaged {@code file} goes; unique because of the millisecond timestamp */
    Path damagedName(Path file, Instant now) {
        Path rel = root.relativize(file.toAbsolutePath().normalize());
        String flat = safe(rel.toString().replace('/', '_').replace('\\', '_'));
        return damagedFolder().resolve(flat + "." + STAMP.format(now));
    }

    static String safe(String s) {
        String out = s.strip().replaceAll("[^A-Za-z0-9._-]", "_");
        return out.isEmpty() || out.startsWith(".") ? "_" + out : out;
    }
}

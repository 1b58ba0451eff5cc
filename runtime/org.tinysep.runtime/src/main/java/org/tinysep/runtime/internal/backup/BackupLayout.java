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

    /**
     * Letters A-Z a-z, digits and {@code . _ -} stay, any other character (code point) becomes {@code _}; a name
     * that would be empty or start with a dot gets a leading {@code _}. A loop, not a regular expression: it runs
     * once per backup written (20,000 at once when a large platform starts).
     */
    static String safe(String s) {
        String t = s.strip();
        StringBuilder out = new StringBuilder(t.length() + 1);
        t.codePoints().forEach(c -> out.append(allowed(c) ? (char) c : '_'));
        return out.isEmpty() || out.charAt(0) == '.' ? "_" + out : out.toString();
    }

    private static boolean allowed(int c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_'
                || c == '-';
    }
}

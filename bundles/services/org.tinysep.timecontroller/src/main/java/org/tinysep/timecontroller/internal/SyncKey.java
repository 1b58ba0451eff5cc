package org.tinysep.timecontroller.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.Optional;
import java.util.Set;
import org.tinysep.link.sync.SyncSecret;

/**
 * The synchroniser's shared secret (docs/time-sync.md, "Authentication"): the text of a key file, by default
 * {@code ${tinysep.var}/sync.key}. A missing file is created with 32 random bytes in hex, mode 0600, atomically
 * (a file that appears meanwhile, e.g. written by scripts/demo-flat.sh, wins). What a key is:
 * {@link SyncSecret}.
 */
final class SyncKey {

    private SyncKey() {
    }

    /** @return the key bytes; creates the file when it is missing */
    static byte[] loadOrCreate(Path file) throws IOException {
        if (!Files.exists(file)) {
            create(file);
        }
        return SyncSecret.read(file);
    }

    private static void create(Path file) throws IOException {
        byte[] random = new byte[32];
        new SecureRandom().nextBytes(random);
        Path dir = file.toAbsolutePath().getParent();
        Files.createDirectories(dir);
        Path tmp = Files.createTempFile(dir, file.getFileName() + ".", ".tmp"); // rw------- on POSIX
        try {
            Files.writeString(tmp, HexFormat.of().formatHex(random) + "\n", StandardCharsets.US_ASCII);
            Files.move(tmp, file, StandardCopyOption.ATOMIC_MOVE);
        } catch (FileAlreadyExistsException someoneElseWasFaster) {
            // keep theirs
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /** @return a warning when other users may read the key file (POSIX only), else empty */
    static Optional<String> exposure(Path file) {
        try {
            Set<PosixFilePermission> p = Files.getPosixFilePermissions(file);
            Set<PosixFilePermission> others = Set.of(PosixFilePermission.GROUP_READ, PosixFilePermission.OTHERS_READ,
                    PosixFilePermission.GROUP_WRITE, PosixFilePermission.OTHERS_WRITE);
            if (p.stream().anyMatch(others::contains)) {
                return Optional.of("the time synchroniser key " + file + " can be read or written by other users ("
                        + PosixFilePermissions.toString(p)
                        + "): anyone who reads it can drive the clock; chmod 600 it");
            }
        } catch (IOException | UnsupportedOperationException e) {
            // not POSIX, or gone: nothing to say
        }
        return Optional.empty();
    }
}

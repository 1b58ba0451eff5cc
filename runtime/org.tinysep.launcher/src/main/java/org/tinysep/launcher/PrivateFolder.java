package org.tinysep.launcher;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.EnumSet;
import java.util.Optional;
import java.util.Set;

/**
 * The state folder holds the house plan, alert texts (event log, mail spool), configuration and secrets: only its
 * owner may enter it (docs/backup.md § File modes). On POSIX file systems {@link #tighten} sets it to
 * {@code rwx------} at every start and says in plain words when other users could read it before.
 */
final class PrivateFolder {

    static final Set<PosixFilePermission> PRIVATE = PosixFilePermissions.fromString("rwx------");

    private PrivateFolder() {
    }

    /**
     * Creates {@code dir} if needed and makes it {@code rwx------}.
     *
     * @return a warning for the user when the folder was open to its group or to everyone; empty otherwise (also on
     *         file systems without POSIX modes)
     */
    static Optional<String> tighten(Path dir) throws IOException {
        boolean existed = Files.isDirectory(dir);
        Files.createDirectories(dir);
        if (!Files.getFileStore(dir).supportsFileAttributeView("posix")) {
            return Optional.empty();
        }
        if (!existed) { // new: made private before anything is in it, nothing to warn about
            Files.setPosixFilePermissions(dir, EnumSet.copyOf(PRIVATE));
            return Optional.empty();
        }
        Set<PosixFilePermission> before = Files.getPosixFilePermissions(dir);
        if (before.equals(PRIVATE)) {
            return Optional.empty();
        }
        Files.setPosixFilePermissions(dir, EnumSet.copyOf(PRIVATE));
        Set<PosixFilePermission> open = EnumSet.noneOf(PosixFilePermission.class);
        open.addAll(before);
        open.removeAll(EnumSet.of(PosixFilePermission.OWNER_READ, PosixFilePermission.OWNER_WRITE,
                PosixFilePermission.OWNER_EXECUTE));
        if (open.isEmpty()) {
            return Optional.empty();
        }
        return Optional.of("State folder " + dir + " was open to other users (" + PosixFilePermissions.toString(before)
                + "), now private (" + PosixFilePermissions.toString(PRIVATE) + "); change any password kept in it");
    }
}

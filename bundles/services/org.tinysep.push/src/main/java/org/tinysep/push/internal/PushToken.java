package org.tinysep.push.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;

/**
 * The push token, kept like the SMTP password: the first line of a file in the secrets folder (default
 * {@code ${tinysep.var}/secrets/push.token}), read for every message, never in the configuration and never in any
 * text this bundle writes.
 */
final class PushToken {

    private PushToken() {
    }

    /** @return the token, or empty when the file does not exist */
    static String read(Path file) throws IOException {
        if (file == null || !Files.exists(file)) {
            return "";
        }
        String all = Files.readString(file, StandardCharsets.UTF_8);
        int eol = all.indexOf('\n');
        return (eol < 0 ? all : all.substring(0, eol)).strip();
    }

    /** @return a warning when others can read the file, else empty */
    static String warning(Path file) {
        try {
            if (file != null && Files.exists(file) && Files.getPosixFilePermissions(file).stream()
                    .anyMatch(p -> p != PosixFilePermission.OWNER_READ && p != PosixFilePermission.OWNER_WRITE
                            && p != PosixFilePermission.OWNER_EXECUTE)) {
                return "the push token file " + file + " can be read by other users of this computer; make it "
                        + "owner-only: chmod 600 " + file;
            }
        } catch (IOException | UnsupportedOperationException e) {
            return "";
        }
        return "";
    }
}

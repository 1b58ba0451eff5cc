package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.Set;

/** Reads a password from the first line of a file (read for every connection, never logged). */
final class Secrets {

    private Secrets() {
    }

    /**
     * @return the first line of the file
     * @throws IOException in plain words when the file is missing or unreadable
     */
    static String firstLine(Path f, String what) throws IOException {
        if (f == null || !Files.exists(f)) {
            throw new IOException("the " + what + " file " + f + " does not exist");
        }
        String all = Files.readString(f, StandardCharsets.UTF_8);
        int eol = all.indexOf('\n');
        String line = eol < 0 ? all : all.substring(0, eol);
        return line.endsWith("\r") ? line.substring(0, line.length() - 1) : line;
    }

    /** @return a warning when others may read the file, else null */
    static String openToOthers(Path f) {
        try {
            Set<PosixFilePermission> p = Files.getPosixFilePermissions(f);
            return p.stream().anyMatch(x -> !x.name().startsWith("OWNER_"))
                    ? "the password file " + f + " can be read by other users of this computer; chmod 600 " + f
                    : null;
        } catch (UnsupportedOperationException | IOException e) {
            return null;
        }
    }
}

package org.tinysep.mailmanager.internal;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * Where the SMTP password comes from. Preferred: the {@code passwordFile} (default
 * {@code ${tinysep.var}/secrets/smtp.password}), read for every attempt and kept out of backups. For compatibility
 * a {@code password} key in the configuration still works and wins, with a warning: ConfigAdmin keeps it in plain
 * text in the framework cache. The password itself never appears in any text this class returns.
 */
final class SmtpPassword {

    private SmtpPassword() {
    }

    /**
     * @return the password for one attempt: the configuration's {@code password} key if set, else the first line of
     *         the password file, else empty (no file)
     * @throws IOException the file exists but cannot be read
     */
    static String read(MailSettings s) throws IOException {
        if (!s.password().isEmpty()) {
            return s.password();
        }
        Path f = s.passwordFile();
        if (!Files.exists(f)) {
            return "";
        }
        String all = Files.readString(f, StandardCharsets.UTF_8);
        int eol = all.indexOf('\n');
        String line = eol < 0 ? all : all.substring(0, eol);
        return line.endsWith("\r") ? line.substring(0, line.length() - 1) : line;
    }

    /** @return plain-words warnings about how the password is kept; empty when all is well or no login is used */
    static List<String> warnings(MailSettings s) {
        List<String> w = new ArrayList<>();
        if (!s.password().isEmpty()) {
            w.add("the SMTP password is set with the key 'password' of configuration " + MailManagerDriver.PID
                    + ": it is stored in plain text in the framework cache and may end up in backups; write it to "
                    + s.passwordFile() + " (readable by its owner only) and remove the 'password' key");
        }
        if (s.user().isEmpty() || !s.password().isEmpty()) {
            return w;
        }
        Path f = s.passwordFile();
        if (!Files.exists(f)) {
            w.add("SMTP user '" + s.user() + "' is set but the password file " + f + " does not exist: the server "
                    + "will refuse the login until it is written");
        } else {
            String open = openTo(f);
            if (open != null) {
                w.add("the SMTP password file " + f + " can be read by other users of this computer (" + open
                        + "); make it owner-only: chmod 600 " + f);
            }
        }
        return w;
    }

    /** @return a description for the device parameter, without the password */
    static String describe(MailSettings s) {
        if (!s.password().isEmpty()) {
            return "from the configuration key 'password' (plain text in the framework cache)";
        }
        Path f = s.passwordFile();
        if (!Files.exists(f)) {
            return f + " (missing)";
        }
        String open = openTo(f);
        return f + (open == null ? " (owner-only)" : " (READABLE BY OTHERS: " + open + ")");
    }

    /** @return the permissions if group or others have any, else null (also on non-POSIX file systems) */
    private static String openTo(Path f) {
        try {
            Set<PosixFilePermission> p = Files.getPosixFilePermissions(f);
            boolean open = p.stream().anyMatch(x -> !x.name().startsWith("OWNER_"));
            return open ? "mode " + PosixFilePermissions.toString(p) : null;
        } catch (UnsupportedOperationException | IOException e) {
            return null;
        }
    }
}

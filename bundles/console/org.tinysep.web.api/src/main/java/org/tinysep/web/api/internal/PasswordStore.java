package org.tinysep.web.api.internal;

import java.io.IOException;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumMap;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * The console's password hashes, one per role. Two sources: the file {@code passwords.properties} in the state
 * folder (written by {@code tinysep:web-password}, atomically, hashes only) and the configuration keys
 * {@code installer.hash} / {@code caregiver.hash}. The file wins for a role it names.
 */
public final class PasswordStore {

    private static final Logger LOG = LoggerFactory.getLogger(PasswordStore.class);
    /** Shortest password accepted from the shell. */
    public static final int MIN_LENGTH = 8;

    private final Path file;
    private final Map<Role, String> configured;

    /**
     * @param file       the hashes file, or null when there is no state folder (then only the configuration counts)
     * @param configured hashes from the configuration (malformed ones are ignored with a warning)
     */
    public PasswordStore(Path file, Map<Role, String> configured) {
        this.file = file;
        this.configured = new EnumMap<>(Role.class);
        configured.forEach((role, hash) -> {
            if (hash == null || hash.isBlank()) {
                return;
            }
            if (PasswordHash.wellFormed(hash)) {
                this.configured.put(role, hash.strip());
            } else {
                LOG.warn("Ignoring {}.hash of the web console configuration: not of the form "
                        + "pbkdf2-sha256:<iterations>:<salt>:<hash> (set a password with tinysep:web-password)", role.id());
            }
        });
    }

    /** @return the stored hash for {@code role}, if a password is set */
    public Optional<String> hash(Role role) {
        String fromFile = fileHashes().get(role.id());
        if (fromFile != null && PasswordHash.wellFormed(fromFile)) {
            return Optional.of(fromFile.strip());
        }
        return Optional.ofNullable(configured.get(role));
    }

    /** @return whether {@code password} is the password of {@code role} (false when none is set) */
    public boolean verify(Role role, String password) {
        return hash(role).map(h -> PasswordHash.matches(password, h)).orElse(false);
    }

    /** @return whether any role has a password (until then nobody can log in) */
    public boolean anySet() {
        for (Role r : Role.values()) {
            if (hash(r).isPresent()) {
                return true;
            }
        }
        return false;
    }

    /**
     * Sets the password of {@code role}: its salted hash replaces the role's line in the file.
     *
     * @throws IllegalArgumentException for a password shorter than {@value #MIN_LENGTH} characters
     * @throws IllegalStateException    when there is no state folder to write to
     */
    public synchronized void set(Role role, String password) {
        if (password == null || password.length() < MIN_LENGTH) {
            throw new IllegalArgumentException("the password must have at least " + MIN_LENGTH + " characters");
        }
        if (file == null) {
            throw new IllegalStateException("no state folder (tinysep.var) to keep the password in: "
                    + "put " + role.id() + ".hash into the configuration org.tinysep.web.api instead");
        }
        Properties p = new Properties();
        p.putAll(fileHashes());
        p.setProperty(role.id(), PasswordHash.create(password));
        StringBuilder text = new StringBuilder("# TinySEP web console: salted PBKDF2 password hashes, one per role "
                + "(set with tinysep:web-password <role> <password>)\n");
        p.stringPropertyNames().stream().sorted()
                .forEach(k -> text.append(k).append('=').append(p.getProperty(k)).append('\n'));
        try {
            AtomicFiles.write(file, text.toString().getBytes(StandardCharsets.ISO_8859_1));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + file + ": " + e.getMessage(), e);
        }
    }

    /** @return where the shell-set hashes are kept, or null */
    public Path file() {
        return file;
    }

    private Map<String, String> fileHashes() {
        if (file == null || !Files.isRegularFile(file)) {
            return Map.of();
        }
        try {
            Properties p = new Properties();
            p.load(new StringReader(Files.readString(file, StandardCharsets.ISO_8859_1)));
            Map<String, String> out = new java.util.HashMap<>();
            p.stringPropertyNames().forEach(k -> out.put(k, p.getProperty(k)));
            return out;
        } catch (IOException e) {
            LOG.warn("Cannot read the web console's password file {}: {}", file, e.toString());
            return Map.of();
        }
    }
}

package org.tinysep.launcher;

import java.io.BufferedReader;
import java.io.Console;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.GeneralSecurityException;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.List;
import java.util.Optional;
import java.util.Properties;
import javax.crypto.SecretKeyFactory;
import javax.crypto.spec.PBEKeySpec;

/**
 * {@code --web-password installer|caregiver}: sets a web console password without the shell, e.g.
 * for daemon mode. It writes the same file and hash form as the shell's {@code tinysep:web-password}
 * ({@code <var>/web/passwords.properties}, {@code pbkdf2-sha256:<iterations>:<salt>:<hash>}, see the web API
 * bundle's PasswordHash; the platform reads the file at each login), atomically, hashes only.
 */
final class WebPassword {

    static final String OPTION = "--web-password";
    static final int MIN_LENGTH = 8;
    private static final int ITERATIONS = 120_000;
    /** Made on first use: every start reads the arguments here, and a SecureRandom loads the security providers. */
    private static final class Random {
        static final SecureRandom RANDOM = new SecureRandom();
    }

    private WebPassword() {
    }

    /** @return the role named after {@code --web-password}, if the option is given */
    static Optional<String> role(List<String> args) {
        int i = args.indexOf(OPTION);
        if (i < 0) {
            return Optional.empty();
        }
        if (i + 1 >= args.size() || !List.of("installer", "caregiver").contains(args.get(i + 1))) {
            throw new IllegalArgumentException(OPTION + " needs a role: installer or caregiver");
        }
        return Optional.of(args.get(i + 1));
    }

    /** @return the arguments without {@code --web-password ROLE} */
    static List<String> rest(List<String> args) {
        int i = args.indexOf(OPTION);
        if (i < 0) {
            return args;
        }
        List<String> rest = new java.util.ArrayList<>(args);
        rest.subList(i, Math.min(i + 2, rest.size())).clear();
        return rest;
    }

    /** Asks for the password (twice on a terminal; one line from standard input otherwise) and stores it. */
    static int run(String role, Path var) {
        try {
            String password = read(role);
            set(var, role, password);
            System.out.println("The " + role + " password of the web console is set (" + file(var) + ").");
            return 0;
        } catch (IllegalArgumentException e) {
            System.err.println(e.getMessage());
            return 2;
        } catch (IOException e) {
            System.err.println("Cannot store the password in " + file(var) + ": " + e.getMessage());
            return 1;
        }
    }

    static Path file(Path var) {
        return var.resolve("web").resolve("passwords.properties");
    }

    /** Stores the salted hash of {@code password} for {@code role}, keeping the other role's line. */
    static void set(Path var, String role, String password) throws IOException {
        if (password == null || password.length() < MIN_LENGTH) {
            throw new IllegalArgumentException("The password is too short: at least " + MIN_LENGTH + " characters.");
        }
        Path file = file(var);
        Files.createDirectories(file.getParent());
        Properties hashes = new Properties();
        if (Files.isRegularFile(file)) {
            hashes.load(new StringReader(Files.readString(file, StandardCharsets.ISO_8859_1)));
        }
        hashes.setProperty(role, hash(password));
        StringBuilder text = new StringBuilder("# web console password hashes (tinysep:web-password)\n");
        hashes.stringPropertyNames().stream().sorted()
                .forEach(k -> text.append(k).append('=').append(hashes.getProperty(k)).append('\n'));
        Path tmp = Files.createTempFile(file.getParent(), "passwords", ".tmp");
        Files.writeString(tmp, text, StandardCharsets.ISO_8859_1);
        Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    static String hash(String password) {
        byte[] salt = new byte[16];
        Random.RANDOM.nextBytes(salt);
        PBEKeySpec spec = new PBEKeySpec(password.toCharArray(), salt, ITERATIONS, 256);
        try {
            byte[] hash = SecretKeyFactory.getInstance("PBKDF2WithHmacSHA256").generateSecret(spec).getEncoded();
            Base64.Encoder b64 = Base64.getEncoder();
            return "pbkdf2-sha256:" + ITERATIONS + ":" + b64.encodeToString(salt) + ":" + b64.encodeToString(hash);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("PBKDF2WithHmacSHA256 is not available in this Java", e);
        } finally {
            spec.clearPassword();
        }
    }

    private static String read(String role) throws IOException {
        Console console = System.console();
        if (console != null) {
            char[] first = console.readPassword("New %s password for the web console: ", role);
            char[] again = console.readPassword("Once more: ");
            if (first == null || again == null || !new String(first).equals(new String(again))) {
                throw new IllegalArgumentException("The two passwords differ: nothing was changed.");
            }
            return new String(first);
        }
        String line = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8)).readLine();
        if (line == null) {
            throw new IllegalArgumentException("No password given on standard input: nothing was changed.");
        }
        return line.strip();
    }
}

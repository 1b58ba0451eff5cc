package org.tinysep.itests;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.GeneralSecurityException;
import java.util.HexFormat;
import java.util.Map;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * The known synchroniser key of the integration tests (docs/time-sync.md, "Authentication"): the Time Controller
 * reads it from {@link #file()} (configuration {@code syncKeyFile}); test synchronisers sign with {@link #KEY}.
 */
public final class TestSyncKey {

    /** The key text, as the Time Controller reads it from the file. */
    public static final String KEY = "itests-known-synchroniser-key-0123456789";

    private TestSyncKey() {
    }

    /** @return the key file ({@code target/itests-sync.key}, mode 0600), written when missing */
    public static synchronized Path file() {
        Path file = Path.of("target", "itests-sync.key").toAbsolutePath();
        try {
            if (!Files.isRegularFile(file) || !Files.readString(file).strip().equals(KEY)) {
                Files.createDirectories(file.getParent());
                Files.writeString(file, KEY + "\n", StandardCharsets.US_ASCII);
                Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-------"));
            }
            return file;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * @param mode REAL or EXTERNAL
     * @return a Time Controller configuration: that mode, the link on a free port of 127.0.0.1, this key, and no
     *         syncTimeout (a test may pause between TICKs as long as the machine needs)
     */
    public static Map<String, String> timeConfig(String mode) {
        return Map.of("mode", mode, "syncPort", "0", "syncBindAddress", "127.0.0.1",
                "syncKeyFile", file().toString(), "syncTimeout", "0");
    }

    /** @return {@code request} followed by its HMAC for {@code session} (from WELCOME) */
    public static String signed(String session, String request) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(KEY.getBytes(StandardCharsets.US_ASCII), "HmacSHA256"));
            return request + " " + HexFormat.of().formatHex(
                    mac.doFinal((session + " " + request).getBytes(StandardCharsets.US_ASCII)));
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException(e);
        }
    }
}

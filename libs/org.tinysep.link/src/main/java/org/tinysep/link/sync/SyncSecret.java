package org.tinysep.link.sync;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.util.HexFormat;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * The synchroniser key and the HMAC that signs a request with it. The key is the key file's text without surrounding
 * white space, as US-ASCII bytes: 16 to 256 printable characters without spaces (the platform writes 64 hex digits).
 * A request {@code <signed>} of session {@code <session>} carries the lower-case hex HMAC-SHA256 of
 * {@code "<session> <signed>"}.
 */
public final class SyncSecret {

    /** The shortest key accepted, in characters. */
    public static final int MIN = 16;
    /** The longest key accepted, in characters. */
    public static final int MAX = 256;

    private SyncSecret() {
    }

    /**
     * @return the key held by {@code file}
     * @throws IOException the file cannot be read, or does not hold a key (the message says what a key looks like)
     */
    public static byte[] read(Path file) throws IOException {
        String text = Files.readString(file, StandardCharsets.US_ASCII).strip();
        if (text.length() < MIN || text.length() > MAX || !text.chars().allMatch(c -> c > 0x20 && c < 0x7F)) {
            throw new IOException("the synchroniser key file " + file + " must hold " + MIN + " to " + MAX
                    + " printable ASCII characters without spaces (e.g. 64 hex digits); the platform writes one "
                    + "when it is missing (delete a damaged one to get a new one)");
        }
        return text.getBytes(StandardCharsets.US_ASCII);
    }

    /** @return the lower-case hex HMAC-SHA256 of {@code "<session> <signed>"} with {@code key} */
    public static String hmac(byte[] key, String session, String signed) {
        return hmacHex(key, (session + " " + signed).getBytes(StandardCharsets.US_ASCII));
    }

    /**
     * The one HMAC of TinySEP's signed messages: the synchroniser's requests ({@link #hmac}) and the signed JSON
     * messages of the MQTT bridge and board ({@code org.tinysep.json.JsonSignature}).
     *
     * @return the lower-case hex HMAC-SHA256 of {@code message} with {@code key}
     */
    public static String hmacHex(byte[] key, byte[] message) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key, "HmacSHA256"));
            return HexFormat.of().formatHex(mac.doFinal(message));
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("HmacSHA256 is part of every Java platform", e);
        }
    }
}

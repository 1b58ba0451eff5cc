package org.tinysep.runtime.internal.backup;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.Optional;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;
import org.tinysep.device.support.files.AtomicFiles;

/**
 * Archive signatures (docs/backup.md § Signed archives): HMAC-SHA256 with this installation's key
 * ({@code ${tinysep.var}/secrets/backup.key}, 32 random bytes, {@code rw-------}, made by the first backup) over
 * every entry in archive order — its name, a zero byte, its content, its length as 8 bytes. The signature is the
 * entry {@value #ENTRY}: a format line, the key's id (first 8 bytes of SHA-256 of the key, in hex: tells a foreign
 * archive from an altered one) and the MAC.
 */
final class ArchiveSignature {

    static final String ENTRY = "tinysep-signature.txt";
    static final String KEY_FILE = "backup.key";
    private static final String FORMAT = "TinySEP archive signature 1";

    private final byte[] key;
    private final String keyId;

    private ArchiveSignature(byte[] key) {
        this.key = key.clone();
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(key);
            this.keyId = HexFormat.of().formatHex(digest, 0, 8);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException(e);
        }
    }

    /** @return the key in {@code keyFile}, made (32 random bytes, rw-------) when there is none */
    static ArchiveSignature loadOrCreate(Path keyFile) throws IOException {
        Optional<ArchiveSignature> existing = load(keyFile);
        if (existing.isPresent()) {
            return existing.get();
        }
        byte[] key = new byte[32];
        new SecureRandom().nextBytes(key);
        AtomicFiles.write(keyFile, (HexFormat.of().formatHex(key) + "\n").getBytes(StandardCharsets.US_ASCII));
        return new ArchiveSignature(key);
    }

    /** @return the key in {@code keyFile}, if there is one */
    static Optional<ArchiveSignature> load(Path keyFile) throws IOException {
        if (!Files.isRegularFile(keyFile)) {
            return Optional.empty();
        }
        String hex = Files.readString(keyFile, StandardCharsets.US_ASCII).strip();
        try {
            byte[] key = HexFormat.of().parseHex(hex);
            if (key.length < 16) {
                throw new IOException(keyFile + " holds no usable key (too short)");
            }
            return Optional.of(new ArchiveSignature(key));
        } catch (IllegalArgumentException e) {
            throw new IOException(keyFile + " holds no usable key: " + e.getMessage());
        }
    }

    String keyId() {
        return keyId;
    }

    /** @return a MAC ready for {@link #begin}, {@code update} and {@link #end} per entry */
    Mac newMac() {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key, "HmacSHA256"));
            return mac;
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("HmacSHA256 is not available: " + e, e);
        }
    }

    static void begin(Mac mac, String name) {
        mac.update(name.getBytes(StandardCharsets.UTF_8));
        mac.update((byte) 0);
    }

    static void end(Mac mac, long length) {
        for (int i = 7; i >= 0; i--) {
            mac.update((byte) (length >>> (8 * i)));
        }
    }

    /** @return the signature entry's content for a finished MAC */
    byte[] entry(Mac mac) {
        return (FORMAT + "\nkey " + keyId + "\nhmac-sha256 " + HexFormat.of().formatHex(mac.doFinal()) + "\n")
                .getBytes(StandardCharsets.US_ASCII);
    }

    /**
     * @param signature the archive's signature entry, or null when it has none
     * @param mac       the MAC computed over the archive's entries with this key
     * @return null when the archive was signed with this installation's key and not changed since; else why not,
     *         in plain words
     */
    String check(byte[] signature, Mac mac) {
        byte[] computed = mac.doFinal();
        if (signature == null) {
            return "the archive is not signed (it was not made by tinysep:backup of this installation)";
        }
        String[] lines = new String(signature, StandardCharsets.US_ASCII).strip().split("\n");
        if (lines.length != 3 || !lines[0].strip().equals(FORMAT) || !lines[1].startsWith("key ")
                || !lines[2].startsWith("hmac-sha256 ")) {
            return "the archive's signature is unreadable";
        }
        String theirKey = lines[1].substring(4).strip();
        if (!theirKey.equals(keyId)) {
            return "the archive was signed by another installation (key " + theirKey + "; this one's is " + keyId
                    + ")";
        }
        byte[] theirs;
        try {
            theirs = HexFormat.of().parseHex(lines[2].substring(12).strip());
        } catch (IllegalArgumentException e) {
            return "the archive's signature is unreadable";
        }
        return MessageDigest.isEqual(theirs, computed) ? null
                : "the archive was changed after this installation signed it";
    }
}

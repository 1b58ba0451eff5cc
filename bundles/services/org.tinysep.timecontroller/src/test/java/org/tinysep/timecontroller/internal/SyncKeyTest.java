package org.tinysep.timecontroller.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The synchroniser key file: created at first use (random, 0600), reused, refused when unusable. */
class SyncKeyTest {

    @TempDir
    Path dir;

    @Test
    void aMissingKeyFileIsCreatedWithARandomKeyReadableOnlyByItsOwner() throws IOException {
        Path file = dir.resolve("state/sync.key");
        byte[] key = SyncKey.loadOrCreate(file);
        assertTrue(new String(key, StandardCharsets.US_ASCII).matches("[0-9a-f]{64}"));
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
        assertArrayEquals(key, SyncKey.loadOrCreate(file), "the same key on the next start");
        assertTrue(SyncKey.exposure(file).isEmpty());
        assertTrue(new String(SyncKey.loadOrCreate(dir.resolve("other.key")), StandardCharsets.US_ASCII)
                .matches("[0-9a-f]{64}"));
        assertTrue(!new String(key).equals(new String(SyncKey.loadOrCreate(dir.resolve("other.key")))), "random");
    }

    @Test
    void aGivenKeyIsUsedAsWrittenAndAnExposedFileIsReported() throws IOException {
        Path file = dir.resolve("sync.key");
        Files.writeString(file, "  a-known-test-key-0123\n");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        assertArrayEquals("a-known-test-key-0123".getBytes(StandardCharsets.US_ASCII), SyncKey.loadOrCreate(file));
        assertTrue(SyncKey.exposure(file).orElseThrow().contains("chmod 600"));
    }

    @Test
    void anUnusableKeyFileIsRefusedWithAReason() throws IOException {
        Path file = dir.resolve("sync.key");
        Files.writeString(file, "short\n");
        IOException e = assertThrows(IOException.class, () -> SyncKey.loadOrCreate(file));
        assertTrue(e.getMessage().contains("16 to 256 printable ASCII"), e.getMessage());
        Files.writeString(file, "with a space in the middle 0123");
        assertThrows(IOException.class, () -> SyncKey.loadOrCreate(file));
    }
}

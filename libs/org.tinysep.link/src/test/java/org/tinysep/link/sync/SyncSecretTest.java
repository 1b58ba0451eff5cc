package org.tinysep.link.sync;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SyncSecretTest {

    @TempDir
    Path dir;

    @Test
    void theSignatureIsTheHexHmacOfSessionAndRequest() {
        // expected value computed independently with Python's hmac module (hashlib.sha256)
        assertEquals("0c475321ea2bc96b7344b65ae1a4c3852a64e53c278b47209b84f7c0c9de6efd", SyncSecret.hmac("a-known-test-key-0123".getBytes(StandardCharsets.US_ASCII), "5f3a",
                "TICK 1 2026-01-01T00:00:00Z"));
    }

    @Test
    void aKeyFileIsReadWithoutSurroundingWhiteSpaceAndRefusedWhenUnusable() throws IOException {
        Path file = dir.resolve("sync.key");
        Files.writeString(file, "  a-known-test-key-0123\n");
        assertArrayEquals("a-known-test-key-0123".getBytes(StandardCharsets.US_ASCII), SyncSecret.read(file));
        for (String bad : new String[] {"", "short", "with a space in the middle 0123", "x".repeat(257)}) {
            Files.writeString(file, bad);
            IOException e = assertThrows(IOException.class, () -> SyncSecret.read(file), bad);
            assertTrue(e.getMessage().contains("16 to 256 printable ASCII"), e.getMessage());
        }
    }
}

package org.tinysep.runtime.internal.backup;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** File names of backups keep letters, digits and {@code . _ -}; everything else becomes one {@code _} each. */
class BackupLayoutTest {

    @Test
    void namesKeepOnlySafeCharacters() {
        assertEquals("AmicaMovement", BackupLayout.safe("AmicaMovement"));
        assertEquals("a-1.2_b", BackupLayout.safe("  a-1.2_b "));
        assertEquals("_ber_K_che_x", BackupLayout.safe("Über Küche/x"));
        assertEquals("a_b", BackupLayout.safe("a\uD83D\uDE00b"), "a character outside the BMP is one character");
        assertEquals("_.hidden", BackupLayout.safe(".hidden"));
        assertEquals("_", BackupLayout.safe("   "));
        assertEquals("_.._", BackupLayout.safe("../"));
    }
}

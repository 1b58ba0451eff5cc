package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PasswordStoreTest {

    @TempDir
    Path dir;

    @Test
    void theShellSetPasswordIsKeptAsAHashOnlyAndSurvivesANewStore() throws Exception {
        Path file = dir.resolve("web").resolve("passwords.properties");
        PasswordStore store = new PasswordStore(file, Map.of());
        assertFalse(store.anySet());
        store.set(Role.CAREGIVER, "long enough 1");
        String text = Files.readString(file);
        assertFalse(text.contains("long enough 1"), text);
        assertTrue(text.contains("caregiver=pbkdf2-sha256:"), text);
        PasswordStore again = new PasswordStore(file, Map.of());
        assertTrue(again.verify(Role.CAREGIVER, "long enough 1"));
        assertFalse(again.verify(Role.INSTALLER, "long enough 1"));
        assertFalse(again.verify(Role.CAREGIVER, "long enough 2"));
    }

    @Test
    void aConfiguredHashWorksAndTheFileWins() {
        Path file = dir.resolve("passwords.properties");
        PasswordStore store = new PasswordStore(file, Map.of(Role.INSTALLER, PasswordHash.create("from the cfg 1"),
                Role.CAREGIVER, "not-a-hash"));
        assertTrue(store.verify(Role.INSTALLER, "from the cfg 1"));
        assertFalse(store.verify(Role.CAREGIVER, "not-a-hash"), "a malformed configured hash lets nobody in");
        store.set(Role.INSTALLER, "from the shell 1");
        assertTrue(store.verify(Role.INSTALLER, "from the shell 1"));
        assertFalse(store.verify(Role.INSTALLER, "from the cfg 1"));
    }

    @Test
    void shortPasswordsAreRefused() {
        PasswordStore store = new PasswordStore(dir.resolve("p"), Map.of());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> store.set(Role.INSTALLER, "short"));
        assertEquals("the password must have at least 8 characters", e.getMessage());
        assertFalse(Files.exists(dir.resolve("p")));
    }
}

package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class PasswordHashTest {

    @Test
    void aHashMatchesItsPasswordOnly() {
        String hash = PasswordHash.create("correct horse");
        assertTrue(hash.startsWith("pbkdf2-sha256:" + PasswordHash.ITERATIONS + ":"), hash);
        assertFalse(hash.contains("correct horse"));
        assertTrue(PasswordHash.matches("correct horse", hash));
        assertFalse(PasswordHash.matches("correct hors", hash));
        assertFalse(PasswordHash.matches("", hash));
    }

    @Test
    void theSaltMakesEveryHashDifferent() {
        assertNotEquals(PasswordHash.create("same password"), PasswordHash.create("same password"));
    }

    @Test
    void malformedHashesMatchNothing() {
        for (String bad : new String[] {null, "", "plain-password", "md5:1:abc:def", "pbkdf2-sha256:10:AAAAAAAAAAA=:AAAAAAAAAAAAAAAAAAAAAA==",
                "pbkdf2-sha256:x:y:z", "pbkdf2-sha256:120000:!!!:???"}) {
            assertFalse(PasswordHash.wellFormed(bad), String.valueOf(bad));
            assertFalse(PasswordHash.matches("plain-password", bad), String.valueOf(bad));
        }
    }
}

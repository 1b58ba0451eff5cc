package org.tinysep.runtime.internal.directory;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

class UidResolverTest {

    static final List<String> UIDS = List.of("amica-node-0012", "amica-node-0013", "amica-movement-0012", "flat-1",
            "flat-10");

    @Test
    void exactUidWinsEvenWhenItIsAPrefixOfAnother() {
        assertEquals("flat-1", UidResolver.resolve("flat-1", UIDS, "device"));
    }

    @Test
    void uniquePrefixOfAtLeastFourCharactersResolves() {
        assertEquals("amica-movement-0012", UidResolver.resolve("amica-mo", UIDS, "device"));
        assertEquals("amica-node-0013", UidResolver.resolve(" amica-node-0013 ", UIDS, "device"));
        assertEquals("flat-10", UidResolver.resolve("flat-10", UIDS, "device"));
    }

    @Test
    void ambiguousPrefixNamesTheCandidates() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> UidResolver.resolve("amica-node", UIDS, "device"));
        assertEquals("'amica-node' is ambiguous: it matches 2 (amica-node-0012, amica-node-0013); give more characters",
                e.getMessage());
    }

    @Test
    void shortPrefixesAreNotAccepted() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> UidResolver.resolve("fla", UIDS, "device"));
        assertEquals("no device with uid 'fla' (a uid prefix needs at least 4 characters)", e.getMessage());
    }

    @Test
    void unknownAndEmptyAreClearErrors() {
        assertEquals("no device matches 'door-9'", assertThrows(IllegalArgumentException.class,
                () -> UidResolver.resolve("door-9", UIDS, "device")).getMessage());
        assertEquals("give a device uid", assertThrows(IllegalArgumentException.class,
                () -> UidResolver.resolve("  ", UIDS, "device")).getMessage());
    }

    @Test
    void longCandidateListsAreShortened() {
        List<String> many = List.of("dev-01", "dev-02", "dev-03", "dev-04", "dev-05", "dev-06", "dev-07");
        assertEquals("dev-01, dev-02, dev-03, dev-04, dev-05, and 2 more", UidResolver.shortList(many));
        assertEquals(7, UidResolver.matches("dev-", many).size());
    }
}

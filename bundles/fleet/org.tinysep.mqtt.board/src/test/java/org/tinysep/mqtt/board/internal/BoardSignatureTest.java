package org.tinysep.mqtt.board.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.testsupport.mqtt.Signed;

/**
 * Issue 25 item 2: the board takes a flat's alert state only from that flat — signed with the flat's key, which
 * the board has in its key folder. Fakes (unsigned, another key, another flat's topic), empty retained deletes, an
 * implausible seq and flats without a key change nothing.
 */
class BoardSignatureTest {

    static final String KEY = "0123456789abcdef-flat-17-key";

    @TempDir
    Path keys;
    final List<String> problems = new ArrayList<>();
    Board board;
    final Instant now = Instant.parse("2026-11-25T14:00:00Z");

    @BeforeEach
    void keysOfFlat17() throws Exception {
        Path k = Files.writeString(keys.resolve("17.key"), KEY + "\n");
        Files.setPosixFilePermissions(k, PosixFilePermissions.fromString("rw-------"));
        board = new Board("tinysep", 100, FlatKeys.read(keys, "*", problems::add));
        assertEquals(List.of(), problems);
    }

    boolean send(String topic, String payload) {
        return board.accept(topic, payload.getBytes(StandardCharsets.UTF_8), now);
    }

    boolean signed(String topic, String json) {
        return send(topic, Signed.sign(KEY, topic, json));
    }

    String state(String alert) {
        return board.find("17").orElseThrow().snapshot().alerts().stream().filter(e -> e.alert().id().equals(alert))
                .map(e -> e.alert().state()).findFirst().orElse("gone");
    }

    @Test
    void theFlatsSignedAlertIsShownFakesAreNot() {
        assertTrue(signed("tinysep/17/alert/3", BoardTest.alert(3, "OPEN", 1)));
        assertEquals("OPEN", state("3"));

        // another client's retained CLEARED with a huge seq, unsigned or signed with another key: ignored
        assertFalse(send("tinysep/17/alert/3", BoardTest.alert(3, "CLEARED", 999_999)));
        assertFalse(send("tinysep/17/alert/3", Signed.sign("another-key-0123456789", "tinysep/17/alert/3",
                BoardTest.alert(3, "CLEARED", 999_999))));
        // the flat's own signed message moved to another topic: the topic is signed too
        assertFalse(send("tinysep/17/alert/3", Signed.sign(KEY, "tinysep/17/alert/4", BoardTest.alert(3, "CLEARED", 5))));
        // the empty retained message that would delete it
        assertFalse(send("tinysep/17/alert/3", ""));
        assertEquals("OPEN", state("3"));
        assertEquals(4, board.totals().unsigned());
        assertTrue(board.find("17").orElseThrow().snapshot().lastBad().contains("not sent with flat 17's key"),
                board.find("17").orElseThrow().snapshot().lastBad());

        // a signed seq far beyond the flat's highest: refused as implausible
        assertFalse(signed("tinysep/17/alert/3", BoardTest.alert(3, "CLEARED", 1 + Flat.MAX_SEQ_JUMP + 1)));
        assertEquals("OPEN", state("3"));
        // the flat's real acknowledgement and clearing
        assertTrue(signed("tinysep/17/alert/3", BoardTest.alert(3, "ACKNOWLEDGED", 2)));
        assertEquals("ACKNOWLEDGED", state("3"));
    }

    @Test
    void aFlatWithoutAKeyIsNoFlatOfTheBoard() {
        assertFalse(send("tinysep/flat-evil/alert/1", BoardTest.alert(1, "OPEN", 1).replace("\"17\"", "\"flat-evil\"")));
        assertFalse(send("tinysep/flat-evil/status", "online"));
        assertFalse(send("tinysep/flat-evil/alert/1", Signed.sign(KEY, "tinysep/flat-evil/alert/1",
                BoardTest.alert(1, "OPEN", 1).replace("\"17\"", "\"flat-evil\""))));
        assertTrue(board.find("flat-evil").isEmpty());
        assertEquals(0, board.flats().size());
        assertEquals(3, board.totals().unknownFlats());
    }

    @Test
    void listedFlatsWithoutAKeyAreProblems() {
        problems.clear();
        FlatKeys k = FlatKeys.read(keys, "17, 18", problems::add);
        assertEquals(1, k.size());
        assertEquals(1, problems.size(), problems.toString());
        assertTrue(problems.get(0).startsWith("Monitoring reduced: the care centre's board ignores flat 18"),
                problems.get(0));
        problems.clear();
        FlatKeys.read(keys.resolve("nothing"), "*", problems::add);
        assertTrue(problems.get(0).startsWith("Monitoring reduced: the care centre's board follows no flat"),
                problems.toString());
    }
}

package org.tinysep.timecontroller.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.tinysep.api.service.ClockMode;

/** The wire format of docs/time-sync.md, byte for byte. */
class SyncMessageTest {

    private static SyncMessage parse(String s) throws SyncMessage.Invalid {
        byte[] b = s.getBytes(StandardCharsets.ISO_8859_1);
        return SyncMessage.parse(b, b.length);
    }

    @Test
    void parsesTheDocumentedRequests() throws Exception {
        assertInstanceOf(SyncMessage.Hello.class, parse("HELLO"));
        assertEquals(new SyncMessage.Tick(1, Instant.parse("2026-11-22T10:00:00Z"), "TICK 1 2026-11-22T10:00:00Z",
                "ab12"), parse("TICK 1 2026-11-22T10:00:00Z ab12"));
        assertEquals(new SyncMessage.Tick(42, Instant.parse("2026-11-22T09:00:01.250Z"),
                "TICK 42 2026-11-22T10:00:01.25+01:00", "CD"),
                parse("tick  42\t2026-11-22T10:00:01.25+01:00 CD\r\n"), "case, white space, offset and line end");
        assertEquals(new SyncMessage.Tick(999999999999999999L, Instant.parse("2026-11-22T10:00:00Z"),
                "TICK 999999999999999999 2026-11-22T10:00:00Z", null),
                parse("TICK 999999999999999999 2026-11-22T10:00:00Z"), "no HMAC: parsed, refused by SyncAuth");
        assertEquals(new SyncMessage.Bye(3, "BYE 3", "ef"), parse("bye 3 ef"));
        assertEquals(new SyncMessage.Bye(4, "BYE 4", null), parse("BYE 4"));
    }

    @Test
    void formatsTheDocumentedAnswers() {
        Instant t = Instant.parse("2026-11-22T10:00:01Z");
        assertEquals("DONE 7 2026-11-22T10:00:01Z", SyncMessage.done(7, t));
        assertEquals("WELCOME 2026-11-22T10:00:01Z EXTERNAL 0011223344556677",
                SyncMessage.welcome(t, ClockMode.EXTERNAL, "0011223344556677"));
        assertEquals("ERROR 7 backwards text", SyncMessage.error("7", "backwards", "text"));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "''                                      | -  | malformed",
        "'   '                                   | -  | malformed",
        "HELLO there                             | -  | malformed",
        "TICK                                    | -  | malformed",
        "TICK 5                                  | 5  | malformed",
        "TICK x 2026-11-22T10:00:00Z             | -  | malformed",
        "TICK -1 2026-11-22T10:00:00Z            | -  | malformed",
        "TICK 1234567890123456789 2026-11-22T10:00:00Z | - | malformed",
        "TICK 5 2026-11-22T10:00:00Z mac extra   | 5  | malformed",
        "BYE                                     | -  | malformed",
        "BYE x                                   | -  | malformed",
        "BYE 5 mac extra                         | 5  | malformed",
        "TICK 5 yesterday                        | 5  | malformed",
        "TICK 5 2026-11-22 10:00:00              | 5  | malformed",
        "TICK 5 2026-13-22T10:00:00Z             | 5  | malformed",
        "TOCK 5 2026-11-22T10:00:00Z             | -  | unknown-command",
        "DONE 5 2026-11-22T10:00:00Z             | -  | unknown-command",
    })
    void rejectsBadRequestsWithSeqAndCode(String text, String seq, String code) {
        SyncMessage.Invalid e = assertThrows(SyncMessage.Invalid.class, () -> parse(text));
        assertEquals(seq, e.seq());
        assertEquals(code, e.code());
        assertTrue(e.answer().startsWith("ERROR " + seq + " " + code + " "), e.answer());
        assertTrue(e.getMessage().length() > 5, "a readable reason: " + e.getMessage());
    }

    @Test
    void rejectsBinaryAndOversizeDatagrams() {
        byte[] binary = {'T', 'I', 'C', 'K', ' ', 0, (byte) 0xFF};
        assertEquals("malformed", assertThrows(SyncMessage.Invalid.class,
                () -> SyncMessage.parse(binary, binary.length)).code());
        byte[] big = ("TICK 1 " + "9".repeat(300)).getBytes(StandardCharsets.US_ASCII);
        assertEquals("too-long", assertThrows(SyncMessage.Invalid.class,
                () -> SyncMessage.parse(big, big.length)).code());
    }

    @Test
    void anUnknownCommandIsAbbreviatedInTheAnswer() {
        SyncMessage.Invalid e = assertThrows(SyncMessage.Invalid.class, () -> parse("X".repeat(200)));
        assertTrue(e.answer().length() < 120, e.answer());
    }
}

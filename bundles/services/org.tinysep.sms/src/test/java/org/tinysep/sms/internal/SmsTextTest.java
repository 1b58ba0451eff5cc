package org.tinysep.sms.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** GSM 7-bit or UCS-2, and at most 3 SMS per message (issue 27, item 2). */
class SmsTextTest {

    @Test
    void gsmTextTakes160PerSmsAnd153PerPartUcs2Takes70And67() {
        assertTrue(SmsText.gsm("Keine Aktivität im Bad seit 14:02, Ölfleck?"));
        assertEquals(1, SmsText.parts("a".repeat(160)));
        assertEquals(2, SmsText.parts("a".repeat(161)));
        assertEquals(3, SmsText.parts("a".repeat(153 * 3)));
        assertEquals(4, SmsText.parts("a".repeat(153 * 3 + 1)));
        assertEquals(161, SmsText.units("€" + "a".repeat(159)), "the euro sign takes two septets");
        assertFalse(SmsText.gsm("Łazienka: brak ruchu"), "Ł is not in the GSM alphabet");
        assertEquals(1, SmsText.parts("Ł" + "a".repeat(69)));
        assertEquals(2, SmsText.parts("Ł" + "a".repeat(70)));
    }

    @Test
    void aLongMessageIsShortenedToThreeSmsAndKeepsHowToAnswer() {
        String tail = "Reply OK 3 if you take care of it.";
        String fitted = SmsText.fit("TinySEP: " + "no activity ".repeat(60), tail, 3);
        assertEquals(3, SmsText.parts(fitted));
        assertTrue(fitted.endsWith("...\n" + tail), fitted);
        String ucs = SmsText.fit("Łazienka " + "x".repeat(300), tail, 2);
        assertEquals(2, SmsText.parts(ucs));
        assertTrue(ucs.endsWith(tail));
        assertEquals("short\n" + tail, SmsText.fit("short", tail, 1));
    }
}

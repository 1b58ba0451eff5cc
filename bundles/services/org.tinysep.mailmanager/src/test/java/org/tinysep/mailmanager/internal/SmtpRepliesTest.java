package org.tinysep.mailmanager.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** RFC 5321: 4yz transient, 5yz permanent, except 552 to RCPT (4.5.3.1.10); no reply = transient (3.8). */
class SmtpRepliesTest {

    @Test
    void rfc5321Classes() {
        assertFalse(SmtpReplies.permanent(552, "RCPT TO:<full@care.test>"), "4.5.3.1.10: temporary, like 452");
        assertFalse(SmtpReplies.permanent(452, "RCPT TO:<a@b>"));
        assertFalse(SmtpReplies.permanent(450, "MAIL FROM:<a@b>"));
        assertFalse(SmtpReplies.permanent(451, "."));
        assertFalse(SmtpReplies.permanent(421, "DATA"));
        assertFalse(SmtpReplies.permanent(0, null), "no reply: broken connection or time-out");
        assertTrue(SmtpReplies.permanent(550, "RCPT TO:<nobody@gone.test>"));
        assertTrue(SmtpReplies.permanent(553, "RCPT TO:<x>"));
        assertTrue(SmtpReplies.permanent(552, "MAIL FROM:<a@b> SIZE=99999999"), "552 to MAIL stays permanent");
        assertTrue(SmtpReplies.permanent(552, "."), "552 after the data (too big) stays permanent (4.2.5)");
        assertTrue(SmtpReplies.permanent(554, "DATA"));
        assertFalse(SmtpReplies.permanent(535, "AUTH LOGIN"), "a refused login is this installation's to fix");
        assertFalse(SmtpReplies.permanent(554, ""), "a refused greeting concerns the server, not the alert");
    }

    @Test
    void verbs() {
        assertEquals("RCPT", SmtpReplies.verb("rcpt to:<a@b>"));
        assertEquals("DATA", SmtpReplies.verb("."));
        assertEquals("", SmtpReplies.verb(null));
        assertEquals("552 5.2.2 mailbox full", SmtpReplies.oneLine(" 552 5.2.2 mailbox\r\n full\n"));
    }
}

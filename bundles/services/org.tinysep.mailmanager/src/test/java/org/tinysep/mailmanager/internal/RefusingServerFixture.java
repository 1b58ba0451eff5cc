package org.tinysep.mailmanager.internal;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * The fixture of the tests against a refusing SMTP server, written once: a fresh spool folder, a
 * {@link MailHarness} closed after each test, the server ({@link SmtpSink} refusing, for good, the "nobody"
 * addresses below and answering {@link #FULL} at RCPT for the "full" ones until {@link #emptyMailboxes()}), and a
 * Mail Manager configuration pointing at it ({@link MailHarness#smtp}) that the test may change before
 * {@code h.start(config)}.
 */
abstract class RefusingServerFixture {

    static final String FULL = "552 5.2.2 mailbox full";
    private static final String[] NOBODY = {"nobody@care.test", "nobody@gone.test"};
    private static final String[] FULL_MAILBOXES = {"full@care.test", "full@kin.test"};

    @TempDir
    Path spool;

    final MailHarness h = new MailHarness();
    SmtpSink server;
    Map<String, Object> config;

    @BeforeEach
    void startServer() throws IOException {
        server = new SmtpSink();
        for (String a : NOBODY) {
            server.refuse(a);
        }
        for (String a : FULL_MAILBOXES) {
            server.mailboxFull(a, true);
        }
        server.start();
        config = MailHarness.smtp(server.port(), spool);
    }

    /** The carer emptied the full mailboxes: RCPT accepts them again. */
    void emptyMailboxes() {
        for (String a : FULL_MAILBOXES) {
            server.mailboxFull(a, false);
        }
    }

    @AfterEach
    void tearDown() {
        h.close();
        server.close();
    }
}

package org.tinysep.mailmanager.internal;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;

/**
 * The fixture of the tests against a {@link RefusingSmtpServer}, written once: a fresh spool folder, a
 * {@link MailHarness} closed after each test, the server, and a Mail Manager configuration pointing at it
 * ({@link MailHarness#smtp}) that the test may change before {@code h.start(config)}.
 */
abstract class RefusingServerFixture {

    @TempDir
    Path spool;

    final MailHarness h = new MailHarness();
    RefusingSmtpServer server;
    Map<String, Object> config;

    @BeforeEach
    void startServer() throws IOException {
        server = new RefusingSmtpServer();
        config = MailHarness.smtp(server.port(), spool);
    }

    @AfterEach
    void tearDown() throws IOException {
        h.close();
        server.close();
    }
}

package org.tinysep.mailmanager.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.testsupport.mail.SmtpSink;

/** The Mail Manager against a real SMTP server ({@link SmtpSink} on 127.0.0.1). */
class MailManagerDeviceTest {

    @TempDir
    Path spool;

    private final MailHarness h = new MailHarness();
    private final SmtpSink server = new SmtpSink();

    @AfterEach
    void tearDown() {
        h.close();
        server.close();
    }

    @Test
    void deliversWithSenderRecipientsSubjectAndBody() throws Exception {
        int port = server.start().port();
        MailManagerProvider mail = h.start(MailHarness.smtp(port, spool)).provider();

        mail.send("Inactivity in the kitchen", "No movement for 2 h.\nPlease call Anna.");

        awaitReceived(2); // one message, two recipients
        SmtpSink.Received m = server.messages().get(0);
        assertEquals("Inactivity in the kitchen", m.subject());
        assertEquals("tinysep@home.test", m.header("From"));
        assertEquals("carer@care.test, family@kin.test", m.header("To"));
        assertEquals(List.of("carer@care.test", "family@kin.test"), m.to(), "the envelope");
        assertEquals("No movement for 2 h.\r\nPlease call Anna.", m.body().strip());
        MailHarness.await("IDLE and spool empty", () -> mail.status() == MailStatus.IDLE && spoolFiles().isEmpty());
        assertTrue(h.eventTexts().contains("mail \"Inactivity in the kitchen\" queued for carer@care.test, "
                + "family@kin.test"), h.eventTexts().toString());
        assertTrue(h.eventTexts().contains("mail \"Inactivity in the kitchen\" delivered to carer@care.test, "
                + "family@kin.test"), h.eventTexts().toString());
    }

    @Test
    void keepsMailWhileServerIsDownAndSendsItExactlyOnceWhenBack() throws Exception {
        int port = server.start().port();
        MailManagerProvider mail = h.start(MailHarness.smtp(port, spool)).provider();
        server.stop();

        mail.send("first", "one");
        mail.send("second", "two");
        MailHarness.await("RETRYING", () -> mail.status() == MailStatus.RETRYING);
        assertTrue(h.statuses.contains(MailStatus.RETRYING), "listeners heard it");
        assertEquals(2, spoolFiles().size(), "both kept on disk while the server is down");

        server.start(); // the same port
        MailHarness.await("IDLE again", () -> mail.status() == MailStatus.IDLE);
        awaitReceived(4);
        assertEquals(List.of("first", "second"), subjectsFor("carer@care.test"), "in order, exactly once");
        assertEquals(List.of("first", "second"), subjectsFor("family@kin.test"));
        assertTrue(spoolFiles().isEmpty());
    }

    @Test
    void passwordNeverAppearsInLogsStatusOrParameters() throws Exception {
        String secret = "Very-Secret-42";
        int port = server.requireLogin("alice", "other-pw").start().port();
        Map<String, Object> config = MailHarness.smtp(port, spool);
        config.put("user", "alice");
        config.put("password", secret);
        MailManagerDevice device = h.start(config);

        device.provider().send("alert", "body");
        MailHarness.await("RETRYING after the refused login",
                () -> device.provider().status() == MailStatus.RETRYING);
        device.invoke("retryNow");
        MailHarness.await("second failure", () -> h.statuses.stream().filter(MailStatus.RETRYING::equals).count() >= 2);

        assertTrue(device.status().detail().contains("the server refused the login of alice"),
                device.status().toString());
        Parameter pw = device.parameters().stream().filter(p -> p.key().equals("password")).findFirst().orElseThrow();
        assertEquals("***", pw.value());
        assertFalse(h.stderr().contains(secret), "SLF4J output");
        assertTrue(h.eventTexts().stream().noneMatch(e -> e.contains(secret)), "event log");
        assertTrue(device.parameters().stream().noneMatch(p -> p.value().contains(secret)), "parameters");
        assertFalse(device.status().toString().contains(secret), "status");
        assertFalse(MailSettings.parse(config, null).toString().contains(secret), "settings");
        assertEquals(1, spoolFiles().size(), "still queued");
    }

    @Test
    void spoolSurvivesARestartOfTheComponent() throws Exception {
        int port = server.start().port();
        server.stop(); // nobody listens yet
        MailManagerProvider mail = h.start(MailHarness.smtp(port, spool)).provider();
        mail.send("before restart 1", "a");
        mail.send("before restart 2", "b");
        MailHarness.await("both spooled", () -> spoolFiles().size() == 2);
        h.stopDevice();
        Files.writeString(spool.resolve("00000000000000000001.mail"), "id=oops\nsubject=half");

        server.start();
        MailManagerDevice again = h.start(MailHarness.smtp(port, spool));

        awaitReceived(4);
        assertEquals(List.of("before restart 1", "before restart 2"), subjectsFor("carer@care.test"));
        assertEquals(List.of("before restart 1", "before restart 2"), subjectsFor("family@kin.test"));
        MailHarness.await("spool empty", () -> spoolFiles().isEmpty());
        assertTrue(Files.exists(spool.resolve("damaged").resolve("00000000000000000001.mail")));
        assertTrue(h.logs.events().stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                && e.message().contains("damaged spool file 00000000000000000001.mail")));
        MailHarness.await("IDLE", () -> again.provider().status() == MailStatus.IDLE); // set after the file goes
    }

    @Test
    void withoutHostMailIsWrittenToTheLog() {
        MailManagerDevice device = h.start(Map.of("spoolDir", spool.toString()));
        MailManagerProvider mail = device.provider();

        mail.send("Help needed", "Nobody moved since 9:00.");

        MailHarness.await("logged", () -> h.stderr().contains("Nobody moved since 9:00."));
        assertTrue(h.stderr().contains("WARN"));
        assertTrue(h.stderr().contains("Help needed"));
        assertEquals(MailStatus.NOT_CONFIGURED, mail.status());
        // the status follows on the mail thread, after the log line
        MailHarness.await("the status says why", () -> device.status().detail()
                .equals("no SMTP host configured: alerts are only written to the log"));
        assertEquals(DeviceStatus.State.UNKNOWN, device.status().state());
        assertEquals("none", device.health().delivery());
        assertTrue(device.parameters().stream().anyMatch(p -> p.key().equals("delivery")
                && p.value().equals("no SMTP host configured: alerts are only written to the log")));
        MailHarness.await("said in the event log", () -> h.eventTexts().contains("mail \"Help needed\" NOT mailed, "
                + "only written to the log (no SMTP host configured: alerts are only written to the log)"));
        assertTrue(spoolFiles().isEmpty());
    }

    private List<Path> spoolFiles() {
        try (Stream<Path> s = Files.list(spool)) {
            return s.filter(p -> p.toString().endsWith(".mail")).toList();
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
    }

    /** Waits for {@code n} (message, recipient) pairs at the server. */
    private void awaitReceived(int n) {
        MailHarness.await(n + " deliveries at the server", () -> server.recipients().size() >= n);
    }

    /** Subjects of the messages received for one recipient, in arrival order. */
    private List<String> subjectsFor(String recipient) {
        return server.messages().stream().filter(m -> m.to().contains(recipient)).map(SmtpSink.Received::subject)
                .toList();
    }
}

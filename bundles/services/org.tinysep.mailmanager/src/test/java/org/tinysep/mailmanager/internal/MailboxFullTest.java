package org.tinysep.mailmanager.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Collections;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;

/**
 * Issue 10, item 5: an SMTP server answering {@code 552 mailbox full} at RCPT made the Mail Manager give the alert
 * up. RFC 5321 4.5.3.1.10: a 552 in reply to RCPT is temporary. The alert must be kept, retried and logged as it
 * really is; only after the give-up age is it failed, loudly, until a delivery succeeds.
 */
class MailboxFullTest extends RefusingServerFixture {

    @Test
    void mailboxFullAtRcptIsRetriedAndLoggedTruthfully() throws Exception {
        config.put("recipients", "full@care.test");
        MailManagerDevice device = h.start(config);
        MailManagerProvider mail = device.provider();

        mail.send("Inactivity alert", "No movement for 2 h.");

        MailHarness.await("a truthful 'failed temporarily' entry", () -> h.eventTexts().stream().anyMatch(e -> e
                .startsWith("mail \"Inactivity alert\" to full@care.test: delivery failed temporarily ("
                        + FULL + " to RCPT), retrying at ")));
        assertTrue(h.eventTexts().contains("mail \"Inactivity alert\" queued for full@care.test"), h.eventTexts()
                .toString());
        // the entry is written during the attempt, the status (and the device's) right after it
        MailHarness.await("RETRYING", () -> mail.status() == MailStatus.RETRYING
                && device.status().state() == DeviceStatus.State.OFFLINE);
        assertTrue(device.status().detail().contains("not delivered yet to full@care.test"), device.status()
                .toString());
        assertTrue(h.logs.events().stream().noneMatch(e -> e.kind() == EventKind.PROBLEM), "not given up");
        assertFalse(Files.exists(spool.resolve("failed")), "nothing failed");
        assertEquals(1, spoolFiles(), "kept in the spool");
        try (var files = Files.list(spool)) { // alert texts: owner-only (issue 10, item 6)
            Path f = files.filter(p -> p.toString().endsWith(".mail")).findFirst().orElseThrow();
            assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(f)));
        }

        emptyMailboxes(); // the carer emptied the mailbox
        MailHarness.await("delivered", () -> server.recipients().contains("full@care.test"));
        MailHarness.await("logged as delivered", () -> h.eventTexts()
                .contains("mail \"Inactivity alert\" delivered to full@care.test"));
        MailHarness.await("IDLE", () -> mail.status() == MailStatus.IDLE);
        assertEquals(DeviceStatus.State.ONLINE, device.status().state());
        assertEquals(0, spoolFiles());
    }

    @Test
    void onlyTheRecipientWhoseMailboxIsFullIsRetried() throws Exception {
        config.put("recipients", "carer@care.test, full@kin.test");
        MailManagerProvider mail = h.start(config).provider();

        mail.send("alert", "x");
        MailHarness.await("delivered to the carer", () -> h.eventTexts()
                .contains("mail \"alert\" delivered to carer@care.test"));
        MailHarness.await("retrying the full mailbox", () -> h.eventTexts().stream()
                .anyMatch(e -> e.startsWith("mail \"alert\" to full@kin.test: delivery failed temporarily")));
        emptyMailboxes();
        MailHarness.await("delivered to the other", () -> h.eventTexts()
                .contains("mail \"alert\" delivered to full@kin.test"));
        assertEquals(1, Collections.frequency(server.recipients(), "carer@care.test"), "the carer once");
        assertEquals(1, Collections.frequency(server.recipients(), "full@kin.test"));
    }

    @Test
    void aLaterAlertIsNotHeldBackByAFullMailbox() throws Exception {
        config.put("recipients", "carer@care.test, full@kin.test");
        config.put("retryInitialSeconds", 600); // far beyond this test's waits
        config.put("retryMaxSeconds", 600);
        MailManagerDevice device = h.start(config);
        MailManagerProvider mail = device.provider();

        mail.send("first", "x");
        MailHarness.await("first retrying", () -> h.eventTexts().stream()
                .anyMatch(e -> e.startsWith("mail \"first\" to full@kin.test: delivery failed temporarily")));
        mail.send("second", "y");
        MailHarness.await("second delivered to the carer at once", () -> h.eventTexts()
                .contains("mail \"second\" delivered to carer@care.test"));
        assertEquals(2, Collections.frequency(server.recipients(), "carer@care.test"));

        emptyMailboxes();
        device.invoke("retryNow");
        MailHarness.await("both delivered to the emptied mailbox",
                () -> Collections.frequency(server.recipients(), "full@kin.test") == 2);
        MailHarness.await("IDLE", () -> mail.status() == MailStatus.IDLE);
        assertEquals(2, Collections.frequency(server.recipients(), "carer@care.test"), "nobody twice");
    }

    @Test
    void givenUpAfterTheMaximumAgeWithTheLastReplyAndShownUntilADeliverySucceeds() throws Exception {
        config.put("recipients", "full@care.test");
        config.put("giveUpAfterSeconds", 2);
        MailManagerDevice device = h.start(config);

        device.provider().send("Inactivity alert", "x");
        MailHarness.await("given up", () -> h.logs.events().stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                && e.message().startsWith("mail \"Inactivity alert\" NOT delivered to full@care.test: given up "
                        + "after ") && e.message().contains("(last reply: " + FULL + " to RCPT)")));
        MailHarness.await("ERROR", () -> device.status().state() == DeviceStatus.State.ERROR);
        assertTrue(device.status().detail().startsWith("mail \"Inactivity alert\" NOT delivered to full@care.test"),
                device.status().toString());
        try (var failed = Files.list(spool.resolve("failed"))) {
            assertEquals(1, failed.count(), "kept in failed/");
        }
        assertEquals(0, spoolFiles());

        MailManagerDevice restarted = h.start(config); // the failure is not forgotten by a restart
        MailHarness.await("ERROR after a restart", () -> restarted.status().state() == DeviceStatus.State.ERROR);
        assertTrue(restarted.health().summary().contains("NOT delivered"), restarted.health().summary());

        emptyMailboxes();
        restarted.provider().send("next", "y");
        MailHarness.await("delivered", () -> h.eventTexts().contains("mail \"next\" delivered to full@care.test"));
        MailHarness.await("ONLINE again", () -> restarted.status().state() == DeviceStatus.State.ONLINE);
        assertFalse(restarted.health().summary().contains("NOT delivered"));
    }

    private long spoolFiles() throws Exception {
        try (var s = Files.list(spool)) {
            return s.filter(p -> p.toString().endsWith(".mail")).count();
        }
    }
}

package org.tinysep.mailmanager.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;

/**
 * Permanent refusals (5xx to MAIL/RCPT/DATA other than 552 to RCPT): failed at once and kept aside, never retried
 * forever, never blocking the next message; the device shows the undelivered alert until a delivery succeeds.
 */
class GivenUpTest extends RefusingServerFixture {

    @Test
    void refusedMessageIsFailedKeptAsideAndTheNextOneIsSent() throws Exception {
        config.put("recipients", "nobody@gone.test");
        MailManagerDevice device = h.start(config);
        MailManagerProvider mail = device.provider();

        mail.send("refused", "x");
        MailHarness.await("failed", () -> h.logs.events().stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                && e.message().startsWith("mail \"refused\" NOT delivered to nobody@gone.test: refused for good "
                        + "by the server, not retried (550 5.1.1 no such user to RCPT)")));
        MailHarness.await("IDLE", () -> mail.status() == MailStatus.IDLE);
        assertEquals(DeviceStatus.State.ERROR, device.status().state(), "an undelivered alert is shown");
        try (var failed = Files.list(spool.resolve("failed"))) {
            assertEquals(1, failed.count(), "kept in failed/");
        }

        config.put("recipients", "nobody@gone.test, carer@care.test");
        device.reconfigure(MailSettings.parse(config, null), null);
        mail.send("partly refused", "y");
        MailHarness.await("sent to the valid recipient", () -> server.recipients().contains("carer@care.test"));
        MailHarness.await("reported", () -> h.eventTexts().contains("mail \"partly refused\" delivered to "
                + "carer@care.test") && h.eventTexts().stream().anyMatch(e -> e.startsWith(
                        "mail \"partly refused\" NOT delivered to nobody@gone.test: refused for good")));
        assertEquals(List.of("carer@care.test"), server.recipients());
        assertTrue(h.statuses.stream().noneMatch(MailStatus.RETRYING::equals), "no retry for a 5xx refusal");
        assertEquals(DeviceStatus.State.ERROR, device.status().state());

        config.put("recipients", "carer@care.test");
        device.reconfigure(MailSettings.parse(config, null), null);
        mail.send("all well", "z");
        MailHarness.await("ONLINE once a mail reached all its recipients",
                () -> device.status().state() == DeviceStatus.State.ONLINE);
    }
}

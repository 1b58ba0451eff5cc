package org.tinysep.mailmanager.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.MailDelivery.Outcome;
import org.tinysep.api.service.MailManagerProvider;

/**
 * Delivery you can see (issue 12, item 4): {@code sendTo} a given address returns the message's id, and
 * {@code delivery(id)} / {@code deliveries()} tell what became of it (sent, retrying, failed, only logged), against
 * a real SMTP server ({@link org.tinysep.testsupport.mail.SmtpSink} refusing some addresses).
 */
class DeliveryOutcomeTest extends RefusingServerFixture {

    @Test
    void eachMessageSaysWhetherItWasSentIsRetriedOrFailed() throws Exception {
        config.put("retryInitialSeconds", 60);
        config.put("retryMaxSeconds", 60);
        MailManagerProvider mail = h.start(config).provider();
        assertEquals(List.of("carer@care.test", "family@kin.test"), mail.recipients());

        String sent = mail.sendTo(List.of("second@care.test"), "escalated", "body");
        String failed = mail.sendTo(List.of("nobody@care.test"), "to nobody", "body");
        String retrying = mail.sendTo(List.of("full@care.test"), "to a full mailbox", "body");
        MailHarness.await("three outcomes", () -> outcome(mail, sent) == Outcome.SENT
                && outcome(mail, failed) == Outcome.FAILED && outcome(mail, retrying) == Outcome.RETRYING);
        assertEquals(List.of("second@care.test"), server.recipients(), "only to the given address");
        MailDelivery f = mail.delivery(failed).orElseThrow();
        assertTrue(f.detail().contains("NOT delivered to nobody@care.test") && f.detail().contains("550"),
                f.detail());
        MailDelivery r = mail.delivery(retrying).orElseThrow();
        assertTrue(r.detail().contains("delivery failed temporarily") && r.detail().contains("552"), r.detail());
        assertEquals(List.of("full@care.test"), r.to());
        assertEquals(List.of(sent, failed, retrying), mail.deliveries().stream().map(MailDelivery::id).toList());
        assertThrows(IllegalArgumentException.class, () -> mail.sendTo(List.of("not an address"), "s", "b"));
    }

    @Test
    void withoutAHostAMessageIsOnlyLoggedAndSaysSo() {
        MailManagerProvider mail = h.start(Map.of()).provider();
        String id = mail.sendTo(List.of(), "alert", "body");
        MailHarness.await("LOGGED_ONLY", () -> outcome(mail, id) == Outcome.LOGGED_ONLY);
        assertTrue(mail.delivery(id).orElseThrow().detail().contains("no SMTP host configured"));
    }

    private static Outcome outcome(MailManagerProvider mail, String id) {
        return mail.delivery(id).map(MailDelivery::outcome).orElse(null);
    }
}

package org.tinysep.itests.mail;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.itests.TinySepTestSupport;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * The Mail Manager bundle in a running framework, sending to a real SMTP server ({@link SmtpSink}) configured
 * through ConfigAdmin; the server goes down and comes back, and the alert arrives exactly once.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class MailManagerTest extends TinySepTestSupport {

    private static final String PID = "org.tinysep.mailmanager";
    private static final String DEVICE = "(tinysep.driver.name=MailManager)";

    @Test
    public void sendsThroughSmtpAndKeepsMailWhileTheServerIsDown() throws Exception {
        MailManagerProvider mail = awaitService(MailManagerProvider.class, DEVICE, TIMEOUT);
        Device device = awaitService(Device.class, DEVICE, TIMEOUT);
        assertEquals("the device exists at once, unconfigured", MailStatus.NOT_CONFIGURED, mail.status());

        Path spool = Files.createTempDirectory("tinysep-mail-spool");
        try (SmtpSink sink = new SmtpSink().start()) {
            configure(PID, Map.of("host", "127.0.0.1", "port", Integer.toString(sink.port()), "security", "NONE",
                    "from", "tinysep@home.test", "recipients", "carer@care.test, family@kin.test",
                    "connectTimeoutSeconds", "2", "retryInitialSeconds", "1", "retryMaxSeconds", "2",
                    "spoolDir", spool.toString()));
            await(TIMEOUT, () -> Integer.toString(sink.port()).equals(parameter(device, "port"))
                    && mail.status() == MailStatus.IDLE, "the new configuration applied");

            mail.send("Inactivity alert", "No movement for 2 h.\n.A line starting with a dot\nEnd.");
            assertTrue("delivered", sink.await(1, TIMEOUT));
            SmtpSink.Received first = sink.messages().get(0);
            assertEquals("tinysep@home.test", first.from());
            assertEquals(List.of("carer@care.test", "family@kin.test"), first.to());
            assertEquals("Inactivity alert", first.subject());
            assertEquals("No movement for 2 h.\r\n.A line starting with a dot\r\nEnd.", first.body().strip());

            sink.stop();
            mail.send("Sent while the server was down", "Still delivered.");
            await(TIMEOUT, () -> mail.status() == MailStatus.RETRYING, "RETRYING while the server is down");
            assertEquals("kept in the spool", 1, spoolFiles(spool));
            assertEquals(1, sink.messages().size());

            sink.start(); // same port
            await(TIMEOUT, () -> mail.status() == MailStatus.IDLE, "IDLE once the server is back");
            assertEquals("exactly once", 2, sink.messages().size());
            assertEquals("Sent while the server was down", sink.messages().get(1).subject());
            assertEquals(0, spoolFiles(spool));

            List<String> log = awaitService(EventLog.class, null, TIMEOUT).recent(200).stream()
                    .map(EventEntry::message).toList();
            assertTrue(log.toString(), log.contains("mail \"Sent while the server was down\" queued for "
                    + "carer@care.test, family@kin.test"));
            assertTrue(log.toString(), log.contains("mail \"Inactivity alert\" delivered to carer@care.test, "
                    + "family@kin.test"));
        }
        Files.deleteIfExists(spool); // empty by now
    }

    @Test
    public void aBadValueIsReportedAndNothingStops() throws Exception {
        Device device = awaitService(Device.class, DEVICE, TIMEOUT);
        configure(PID, Map.of("host", "127.0.0.1", "port", "not-a-port", "from", "a@b.test", "recipients", "c@d.test"));
        await(Duration.ofSeconds(10), () -> device.status().detail().contains("port must be a whole number"),
                "the bad value reported in the device status");
        assertEquals("ERROR", device.status().state().name());
        MailManagerProvider mail = awaitService(MailManagerProvider.class, DEVICE, TIMEOUT);
        mail.send("still accepted", "written to the log");
        // the outbox takes the refused configuration on its own thread: its status follows
        await(Duration.ofSeconds(10), () -> mail.status() == MailStatus.NOT_CONFIGURED,
                "the outbox to say NOT_CONFIGURED");
    }

    /** Issue 10, item 5: 552 at RCPT is temporary (RFC 5321 4.5.3.1.10): retried, logged as it is, delivered. */
    @Test
    public void aFullMailboxIsRetriedAndLoggedTruthfully() throws Exception {
        MailManagerProvider mail = awaitService(MailManagerProvider.class, DEVICE, TIMEOUT);
        Path spool = Files.createTempDirectory("tinysep-mail-spool");
        try (SmtpSink sink = new SmtpSink().start()) {
            sink.mailboxFull("full@care.test", true);
            configure(PID, Map.of("host", "127.0.0.1", "port", Integer.toString(sink.port()), "security", "NONE",
                    "from", "tinysep@home.test", "recipients", "full@care.test", "retryInitialSeconds", "1",
                    "retryMaxSeconds", "1", "spoolDir", spool.toString()));
            // not just delivery=smtp: an earlier test of this class may have left smtp to another sink configured
            String through = "127.0.0.1:" + sink.port() + " to full@care.test";
            await(TIMEOUT, () -> driverProperty(MailManagerTest.DELIVERY).equals("smtp")
                    && driverProperty("tinysep.mail.summary").contains(through), "delivery=smtp through " + through);

            mail.send("Inactivity alert (full mailbox)", "x");
            EventLog events = awaitService(EventLog.class, null, TIMEOUT);
            await(TIMEOUT, () -> events.recent(200).stream().anyMatch(e -> e.message().startsWith(
                    "mail \"Inactivity alert (full mailbox)\" to full@care.test: delivery failed temporarily "
                            + "(552 5.2.2 mailbox full to RCPT), retrying at ")), "a truthful entry");
            // the entry is written during the attempt, the status right after it
            await(TIMEOUT, () -> mail.status() == MailStatus.RETRYING, "RETRYING");
            assertTrue(events.recent(200).stream().noneMatch(e -> e.kind() == EventKind.PROBLEM
                    && e.message().contains("full mailbox")));

            sink.mailboxFull("full@care.test", false);
            assertTrue("delivered", sink.await(1, TIMEOUT));
            await(TIMEOUT, () -> events.recent(200).stream().anyMatch(e -> e.message().equals(
                    "mail \"Inactivity alert (full mailbox)\" delivered to full@care.test")), "logged as delivered");
        }
    }

    /** Issue 10, item 5: with no SMTP host the driver figures, service properties and device status say so. */
    @Test
    public void withoutHostTheDriverSaysAlertsOnlyGoToTheLog() throws Exception {
        configure(PID, Map.of("host", ""));
        Device device = awaitService(Device.class, DEVICE, TIMEOUT);
        String plainly = "no SMTP host configured: alerts are only written to the log";
        await(TIMEOUT, () -> driverProperty(DELIVERY).equals("none"), "delivery=none");
        assertEquals(plainly, driverProperty("tinysep.mail.summary"));
        await(TIMEOUT, () -> device.status().detail().equals(plainly), "the device status");
        String drivers = shell("tinysep:drivers");
        assertTrue(drivers, drivers.contains("delivery=none"));
        assertTrue(drivers, drivers.contains(plainly));
    }

    private static final String DELIVERY = "tinysep.mail.delivery";

    /** @return a property of the Mail Manager's Driver service, or "" */
    private String driverProperty(String key) {
        try {
            ServiceReference<Driver> ref = context.getServiceReferences(Driver.class, DEVICE).stream().findFirst()
                    .orElse(null);
            Object v = ref == null ? null : ref.getProperty(key);
            return v == null ? "" : v.toString();
        } catch (org.osgi.framework.InvalidSyntaxException e) {
            throw new AssertionError(e);
        }
    }

    private static String parameter(Device device, String key) {
        return device.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElse("");
    }

    private static long spoolFiles(Path spool) throws Exception {
        try (var s = Files.list(spool)) {
            return s.filter(p -> p.toString().endsWith(".mail")).count();
        }
    }
}

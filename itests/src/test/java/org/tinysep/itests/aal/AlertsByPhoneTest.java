package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.channel.MessageChannel;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.Occupancy;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.testsupport.mail.SmtpSink;
import org.tinysep.testsupport.phone.GammuSmsd;
import org.tinysep.testsupport.phone.PushSink;

/**
 * Alerts by phone (issue 27) end to end in virtual time: a real AmICA movement node over UDP, Inactivity
 * Recognition, the alert service, the SMS channel on the real gammu-smsd (Gammu's dummy modem), the push channel
 * on a local HTTPS server, the Mail Manager on a real SMTP server. Eva is reached by SMS (else by mail), Otto by
 * push; repeat every 10 min, escalate every 15 min. An unplugged modem (gammu-smsd not running) is a device in
 * ERROR while the alert goes by mail and push.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class AlertsByPhoneTest extends AalTestSupport {

    static final String EVA_PHONE = "+4915112345678";
    static final String CONTACTS = "Eva <sms:" + EVA_PHONE + " mail:eva@care.test>, Otto <push:otto-topic>";
    private static final int LIMIT = 45 * 60;

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts", "org.tinysep.sms", "org.tinysep.push");
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.inactivity", INACTIVITY_UTC);
        configs.put("org.tinysep.alerts", Map.of("contacts", CONTACTS, "repeatMinutes", "10", "escalateMinutes",
                "15", "summaryTime", "", "timeZone", "UTC"));
        return configs;
    }

    /** The flat, the phones and the servers; the SMS channel and the push channel configured on them. */
    private final class Flat implements AutoCloseable {
        final Path dir = Files.createTempDirectory("tinysep-phone-");
        final SmtpSink mail = new SmtpSink().start();
        final GammuSmsd smsd = new GammuSmsd(dir.resolve("gammu"));
        final PushSink push = new PushSink(Files.createDirectories(dir.resolve("push")), "tk_test").start();
        final SyncPeer sync = sync();
        final AmicaNode bath = node(1, 40, MOVEMENT);
        final Instant t = tomorrow();
        final AlertService alerts;
        final MessageChannel sms;

        Flat(boolean modem) throws Exception {
            if (modem) {
                smsd.start();
            }
            Path token = Files.writeString(dir.resolve("push.token"), "tk_test\n");
            configure("org.tinysep.sms", Map.of("spoolFolder", smsd.spool().toString(), "pidFile",
                    smsd.pidFile().toString(), "pollMillis", "100", "stuckSeconds", "30"));
            configure("org.tinysep.push", Map.of("server", push.url(), "tokenFile", token.toString(),
                    "trustedCertificates", push.certificatePem().toString()));
            mailTo(mail, "carer@care.test");
            sms = awaitService(MessageChannel.class, "(&(channel.scheme=sms)(spoolFolder=" + smsd.spool() + "))",
                    TIMEOUT);
            awaitService(MessageChannel.class, "(&(channel.scheme=push)(server=" + push.url() + "))", TIMEOUT);
            alerts = awaitService(AlertService.class, null, TIMEOUT);
            sync.tickDone(t);
            placeIn(bath, "AmicaMovement", "Bathroom");
            InactivityRecognitionProvider inactivity = awaitService(InactivityRecognitionProvider.class, null,
                    TIMEOUT);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            bath.motion(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "the flat OCCUPIED");
            await(TIMEOUT, () -> inactivity.state() == InactivityState.WATCHING, "WATCHING");
        }

        Alert collapse() throws Exception {
            sync.tickDone(at(LIMIT));
            assertEquals("one open alert", 1, alerts.open().size());
            return alerts.open().get(0);
        }

        Instant at(int seconds) {
            return t.plusSeconds(seconds);
        }

        Alert alert(String id) {
            return alerts.alert(id).orElseThrow();
        }

        @Override
        public void close() throws Exception {
            bath.close();
            sync.close();
            smsd.close();
            push.close();
            mail.close();
        }
    }

    @Test
    public void anAlertReachesThePhoneBySmsAndAReplyAcknowledgesIt() throws Exception {
        assumeTrue("gammu-smsd (scripts/install-deps.sh)", GammuSmsd.installed());
        try (Flat f = new Flat(true)) {
            await(TIMEOUT, () -> f.sms.status().state() == DeviceStatus.State.ONLINE, "the SMS channel ONLINE: "
                    + f.sms.status());
            Alert a = f.collapse();
            long raised = System.nanoTime();
            Notification first = a.notifications().get(0);
            assertEquals(a.notifications().toString(), "sms", first.channel());
            assertEquals(List.of("Eva"), first.to());
            await(TIMEOUT, () -> sent(f).size() == 1, "the SMS sent by gammu-smsd");
            long millis = (System.nanoTime() - raised) / 1_000_000;
            assertTrue("the SMS left within 5 s, took " + millis + " ms", millis < 5000);
            assertTrue(sent(f).get(0), sent(f).get(0).startsWith(EVA_PHONE + ": TinySEP: no activity in Bathroom")
                    && sent(f).get(0).endsWith("Reply OK " + a.id() + " if you take care of it."));
            System.out.println("AlertsByPhoneTest: alert raised -> SMS in gammu-smsd's sent folder: " + millis + " ms");

            f.smsd.phoneSends(EVA_PHONE, "OK " + a.id());
            await(TIMEOUT, () -> f.alert(a.id()).state() == AlertState.ACKNOWLEDGED, "acknowledged by the reply");
            assertTrue(f.alert(a.id()).closedBy(), f.alert(a.id()).closedBy().startsWith("Eva (SMS reply from "
                    + EVA_PHONE));
            await(TIMEOUT, () -> sent(f).size() == 2, "the confirmation SMS");
            assertEquals(EVA_PHONE + ": TinySEP: alert " + a.id() + " acknowledged by Eva. It is not repeated or "
                    + "passed on any more.", sent(f).get(1));
            int messages = f.alert(a.id()).notifications().size();
            f.sync.tickDone(f.at(LIMIT + 60 * 60));
            assertEquals("no repeat or escalation after the reply", messages,
                    f.alert(a.id()).notifications().size());
            assertTrue(f.push.published().isEmpty());

            f.smsd.phoneSends("+4917099999999", "OK " + a.id());
            await(TIMEOUT, () -> events().contains("SMS reply from +4917099999999 refused"), "the refusal logged");
            Thread.sleep(1000);
            assertEquals("nothing sent back to an unknown number", 2, sent(f).size());
        }
    }

    @Test
    public void nobodyAnswersTheSmsSoTheNextContactIsReachedByPush() throws Exception {
        assumeTrue("gammu-smsd (scripts/install-deps.sh)", GammuSmsd.installed());
        try (Flat f = new Flat(true)) {
            await(TIMEOUT, () -> f.sms.status().state() == DeviceStatus.State.ONLINE, "the SMS channel ONLINE");
            Alert a = f.collapse();
            await(TIMEOUT, () -> sent(f).size() == 1, "the SMS to Eva");
            f.sync.tickDone(f.at(LIMIT + 15 * 60 - 1));
            assertTrue("nobody else before the escalation", f.push.published().isEmpty());
            f.sync.tickDone(f.at(LIMIT + 15 * 60));
            Notification last = lastOf(f.alert(a.id()));
            assertEquals(f.alert(a.id()).notifications().toString(), NotificationStep.ESCALATION, last.step());
            assertEquals(List.of("Otto"), last.to());
            assertEquals("push", last.channel());
            assertEquals(MailDelivery.Outcome.SENT, pushOutcome(f, a, LIMIT + 15 * 60).outcome());
            assertEquals(1, f.push.published().size());
            String json = f.push.published().get(0).body();
            assertTrue(json, json.contains("\"topic\":\"otto-topic\"") && json.contains("ESCALATED, not acknowledged "
                    + "for 15 min") && json.contains("Reply OK " + a.id()));
            assertTrue(events(), events().contains("alert " + a.id() + " not acknowledged: passed on to the next "
                    + "contact, Otto (contact 2 of 2) to Otto by push to otto-topic"));
            String listed = shell("tinysep:alerts");
            assertTrue(listed, listed.contains("ESCALATION to Otto by push"));
        }
    }

    @Test
    public void anUnpluggedModemIsAnErrorAndTheAlertGoesByMail() throws Exception {
        try (Flat f = new Flat(false)) { // gammu-smsd not running: the modem unplugged
            await(TIMEOUT, () -> f.sms.status().state() == DeviceStatus.State.ERROR, "the SMS channel in ERROR");
            assertTrue(f.sms.status().detail(), f.sms.status().detail().startsWith("gammu-smsd is not running"));
            Alert a = f.collapse();
            List<Notification> ns = a.notifications();
            assertEquals(ns.toString(), 2, ns.size());
            assertEquals("sms", ns.get(0).channel());
            assertEquals(MailDelivery.Outcome.FAILED, ns.get(0).outcome());
            assertTrue(ns.get(0).detail(), ns.get(0).detail().startsWith("gammu-smsd is not running"));
            assertEquals(Notification.MAIL, ns.get(1).channel());
            assertTrue("the mail to Eva", f.mail.await(1, TIMEOUT));
            assertEquals(List.of("eva@care.test"), f.mail.messages().get(0).to());
            assertTrue(events(), events().contains("alert " + a.id() + ": first message to Eva by e-mail to "
                    + "eva@care.test (handed to the Mail Manager), because SMS to " + EVA_PHONE + " failed: "
                    + "gammu-smsd is not running"));
            assertTrue(events(), events().contains("SMS channel in ERROR: gammu-smsd is not running"));
            String channels = shell("tinysep:channels");
            assertTrue(channels, channels.contains("sms: SMS through the GSM modem (gammu-smsd) - ERROR (gammu-smsd is "
                    + "not running") && channels.contains("push: push notification (ntfy) - "));

            // the modem is a device in ERROR, in words, in the platform's device list
            Device modem = awaitService(Device.class, "(" + DeviceProperties.DEVICE_TYPE + "=SmsModem)", TIMEOUT);
            assertEquals(modem.status().toString(), DeviceStatus.State.ERROR, modem.status().state());
            assertTrue(modem.status().detail(), modem.status().detail().startsWith("the GSM modem cannot send SMS: "
                    + "gammu-smsd is not running (its pid file " + f.smsd.pidFile() + " does not exist)"));
            String devices = shell("tinysep:devices");
            assertTrue(devices, devices.contains("SmsModem \"GSM modem (gammu-smsd)\" [ERROR (the GSM modem cannot "
                    + "send SMS: gammu-smsd is not running"));

            // and the alert still goes on: Otto by push at the escalation, the modem still in ERROR
            f.sync.tickDone(f.at(LIMIT + 15 * 60));
            Notification last = lastOf(f.alert(a.id()));
            assertEquals(List.of("Otto"), last.to());
            assertEquals("push", last.channel());
            assertEquals(MailDelivery.Outcome.SENT, pushOutcome(f, a, LIMIT + 15 * 60).outcome());
            assertEquals(1, f.push.published().size());
            assertEquals(DeviceStatus.State.ERROR, modem.status().state());
        }
    }

    private static Notification lastOf(Alert a) {
        return a.notifications().get(a.notifications().size() - 1);
    }

    /**
     * @return the last notification of {@code a} once the push channel told its outcome: the push is published on
     *         the channel's own thread and the alert service reads the outcome on its next tick, so platform time
     *         goes on a second at a time from {@code from}
     */
    private Notification pushOutcome(Flat f, Alert a, int from) throws Exception {
        int s = from;
        long end = System.nanoTime() + TIMEOUT.toNanos();
        while (lastOf(f.alert(a.id())).outcome() == MailDelivery.Outcome.QUEUED && System.nanoTime() < end) {
            Thread.sleep(100);
            f.sync.tickDone(f.at(++s));
        }
        return lastOf(f.alert(a.id()));
    }

    private static List<String> sent(Flat f) {
        try {
            return f.smsd.sent();
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
    }

    private String events() {
        EventLog log = awaitService(EventLog.class, null, TIMEOUT);
        StringBuilder b = new StringBuilder();
        log.recent(2000).forEach(e -> b.append(e.origin()).append(": ").append(e.message()).append('\n'));
        return b.toString();
    }
}

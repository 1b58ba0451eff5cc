package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.Bundle;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.MailDelivery;
import org.tinysep.api.service.Occupancy;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * Acknowledgement and escalation (issue 12, item 3) end to end in virtual time: a real AmICA movement node over
 * UDP in the bathroom, Inactivity Recognition, the alert service ({@code org.tinysep.alerts}) and the Mail Manager
 * sending to a real SMTP server. Contacts first, second, third; repeat every 10 min, escalate every 15 min.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class AlertEscalationTest extends AalTestSupport {

    static final String FIRST = "first@care.test";
    static final String SECOND = "second@care.test";
    static final String THIRD = "third@care.test";
    static final String CARER = "carer@care.test";
    private static final int LIMIT = 45 * 60; // the bathroom's limit

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts");
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.inactivity", INACTIVITY_UTC);
        configs.put("org.tinysep.alerts", Map.of("contacts", FIRST + ", " + SECOND + ", " + THIRD,
                "repeatMinutes", "10", "escalateMinutes", "15", "summaryTime", "", "timeZone", "UTC"));
        return configs;
    }

    /** A collapse in the bathroom: the alert raised at t + 45 min, its first message to the first contact. */
    private final class Flat implements AutoCloseable {
        final SmtpSink sink = new SmtpSink().start();
        final SyncPeer sync = sync();
        final AmicaNode bath = node(1, 40, MOVEMENT);
        final Instant t = tomorrow();
        AlertService alerts;
        InactivityRecognitionProvider inactivity;

        Flat() throws Exception {
            mailTo(sink, CARER);
            alerts = awaitService(AlertService.class, null, TIMEOUT);
            sync.tickDone(t);
            placeIn(bath, "AmicaMovement", "Bathroom");
            inactivity = awaitService(InactivityRecognitionProvider.class, null, TIMEOUT);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            bath.motion(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "the flat OCCUPIED");
            await(TIMEOUT, () -> inactivity.state() == InactivityState.WATCHING, "WATCHING");
        }

        /** @return the alert raised at the bathroom's limit, with its first message */
        Alert collapse() throws Exception {
            sync.tickDone(at(LIMIT - 1));
            assertTrue("no alert before the limit", alerts.open().isEmpty());
            sync.tickDone(at(LIMIT));
            assertEquals(InactivityState.ALERT, inactivity.state());
            assertEquals("one open alert", 1, alerts.open().size());
            Alert a = alerts.open().get(0);
            assertEquals("Bathroom", a.roomName());
            assertEquals(1, a.notifications().size());
            assertEquals(NotificationStep.FIRST, a.notifications().get(0).step());
            assertEquals(List.of(FIRST), a.notifications().get(0).to());
            assertTrue("first message mailed", sink.await(1, TIMEOUT));
            assertEquals(List.of(FIRST), sink.messages().get(0).to());
            assertTrue(subject(0), subject(0).startsWith("TinySEP: no activity in Bathroom since "
                    + DateTimeFormatter.ofPattern("HH:mm").withZone(ZoneOffset.UTC).format(t)));
            return a;
        }

        Instant at(int seconds) {
            return t.plusSeconds(seconds);
        }

        String subject(int i) {
            return unfolded(sink.messages().get(i).data());
        }

        Alert alert(String id) {
            return alerts.alert(id).orElseThrow();
        }

        @Override
        public void close() {
            bath.close();
            sync.close();
            sink.close();
        }
    }

    /** The Subject header with folded lines joined (Jakarta Mail folds long subjects). */
    static String unfolded(String data) {
        String headers = data.substring(0, Math.max(0, data.indexOf("\r\n\r\n"))).replace("\r\n ", " ")
                .replace("\r\n\t", " ");
        for (String line : headers.split("\r\n")) {
            if (line.regionMatches(true, 0, "Subject:", 0, 8)) {
                return line.substring(8).strip();
            }
        }
        return "";
    }

    @Test
    public void anUnacknowledgedAlertIsRepeatedAndEscalatedOnSchedule() throws Exception {
        try (Flat f = new Flat()) {
            Alert a = f.collapse();
            int first = LIMIT;
            f.sync.tickDone(f.at(first + 10 * 60 - 1));
            assertEquals("nothing before the repeat period", 1, f.alert(a.id()).notifications().size());
            f.sync.tickDone(f.at(first + 10 * 60));
            assertStep(f.alert(a.id()), 1, NotificationStep.REPEAT, List.of(FIRST));
            f.sync.tickDone(f.at(first + 15 * 60 - 1));
            assertEquals(2, f.alert(a.id()).notifications().size());
            f.sync.tickDone(f.at(first + 15 * 60));
            assertStep(f.alert(a.id()), 2, NotificationStep.ESCALATION, List.of(SECOND));
            assertEquals(2, f.alert(a.id()).contactsReached());
            f.sync.tickDone(f.at(first + 25 * 60)); // the repeat period starts again after the escalation
            assertStep(f.alert(a.id()), 3, NotificationStep.REPEAT, List.of(FIRST, SECOND));
            f.sync.tickDone(f.at(first + 30 * 60));
            assertStep(f.alert(a.id()), 4, NotificationStep.ESCALATION, List.of(THIRD));

            assertTrue("five messages mailed", f.sink.await(5, TIMEOUT));
            assertEquals(List.of(FIRST), f.sink.messages().get(1).to());
            assertTrue(f.subject(1), f.subject(1).startsWith("REPEATED, not acknowledged for 10 min: TinySEP: no "
                    + "activity in Bathroom"));
            assertEquals(List.of(SECOND), f.sink.messages().get(2).to());
            assertTrue(f.subject(2), f.subject(2).startsWith("ESCALATED, not acknowledged for 15 min"));
            assertEquals(List.of(FIRST, SECOND), f.sink.messages().get(3).to());
            assertEquals(List.of(THIRD), f.sink.messages().get(4).to());
            assertTrue(f.sink.messages().get(4).body(), f.sink.messages().get(4).body()
                    .contains("tinysep:ack " + a.id()));
            // each message's outcome is visible in the alert (the Mail Manager's word on it)
            // the Mail Manager's word is read at each platform second
            int s = first + 30 * 60;
            long end = System.nanoTime() + TIMEOUT.toNanos();
            while (!f.alert(a.id()).notifications().stream().allMatch(n -> n.outcome() == MailDelivery.Outcome.SENT)) {
                assertTrue("every notification SENT: " + f.alert(a.id()).notifications(), System.nanoTime() < end);
                f.sync.tickDone(f.at(++s));
                Thread.sleep(20);
            }
            String listed = shell("tinysep:alerts");
            assertTrue(listed, listed.contains("alert " + a.id() + "  OPEN") && listed.contains("ESCALATION to "
                    + THIRD) && listed.contains("SENT"));
            String mails = shell("tinysep:mails");
            assertTrue(mails, mails.contains("SENT") && mails.contains("delivered to " + THIRD));
            assertTrue(events().contains("alert " + a.id() + " not acknowledged: passed on to the next contact, "
                    + SECOND + " (contact 2 of 3)"));
        }
    }

    @Test
    public void anAcknowledgedAlertIsNeitherRepeatedNorEscalated() throws Exception {
        try (Flat f = new Flat()) {
            Alert a = f.collapse();
            String said = shell("tinysep:ack " + a.id() + " Anna");
            assertTrue(said, said.contains("acknowledged by Anna"));
            assertEquals(AlertState.ACKNOWLEDGED, f.alert(a.id()).state());
            assertTrue(f.alerts.open().isEmpty());
            for (int m = 1; m <= 60; m++) {
                f.sync.tickDone(f.at(LIMIT + m * 60));
            }
            assertEquals("no message after the acknowledgement", 1, f.alert(a.id()).notifications().size());
            assertTrue(events().contains("alert " + a.id() + " acknowledged by Anna"));
            String again = shellFails("tinysep:ack " + a.id() + " Bob");
            assertTrue(again, again.contains("is not open: acknowledged") && again.contains("Anna"));
            assertTrue(shellFails("tinysep:ack 999").contains("there is no alert 999"));
            assertEquals(1, f.sink.messages().size());
        }
    }

    @Test
    public void activityAgainSendsTheAllClear() throws Exception {
        try (Flat f = new Flat()) {
            Alert a = f.collapse();
            f.sync.tickDone(f.at(LIMIT + 16 * 60)); // repeated and escalated to the second contact meanwhile
            assertEquals(2, f.alert(a.id()).contactsReached());
            f.bath.motion(true);
            await(TIMEOUT, () -> f.alert(a.id()).state() == AlertState.CLEARED, "the alert cleared");
            Alert c = f.alert(a.id());
            assertTrue(c.closedBy(), c.closedBy().contains("the person is active again"));
            assertStep(c, c.notifications().size() - 1, NotificationStep.ALL_CLEAR, List.of(FIRST, SECOND));
            await(TIMEOUT, () -> f.sink.messages().stream().anyMatch(m -> unfolded(m.data()).startsWith(
                    "All clear: TinySEP: no activity in Bathroom")), "the all clear mailed");
            assertTrue(events().contains("alert " + a.id() + " cleared: the person is active again"));
            int sent = c.notifications().size();
            f.sync.tickDone(f.at(LIMIT + 40 * 60 - 1)); // before the next deadline (activity + 45 min)
            assertEquals("nothing after the all clear", sent, f.alert(a.id()).notifications().size());
        }
    }

    @Test
    public void anOpenAlertIsStillOpenAfterARestartAndEscalationGoesOn() throws Exception {
        try (Flat f = new Flat()) {
            Alert a = f.collapse();
            Bundle alertsBundle = java.util.Arrays.stream(context.getBundles())
                    .filter(b -> b.getSymbolicName().equals("org.tinysep.alerts")).findFirst().orElseThrow();
            alertsBundle.stop();
            await(TIMEOUT, () -> context.getServiceReference(AlertService.class) == null, "the alert service gone");
            alertsBundle.start();
            AlertService again = awaitService(AlertService.class, null, TIMEOUT);
            Alert restored = again.alert(a.id()).orElseThrow();
            assertEquals(AlertState.OPEN, restored.state());
            assertEquals(a.subject(), restored.subject());
            assertEquals(1, restored.notifications().size());
            assertTrue(events().contains("restored after a restart: 1 open alert(s)"));
            f.sync.tickDone(f.at(LIMIT + 15 * 60)); // the schedule counts from the first message, before the restart
            Alert later = again.alert(a.id()).orElseThrow();
            assertStep(later, later.notifications().size() - 1, NotificationStep.ESCALATION, List.of(SECOND));
        }
    }

    @Test
    public void theDailySummaryArrivesAtTheSetTime() throws Exception {
        try (Flat f = new Flat()) {
            Instant due = f.at(2 * 3600).truncatedTo(java.time.temporal.ChronoUnit.MINUTES);
            String hhmm = DateTimeFormatter.ofPattern("HH:mm").withZone(ZoneOffset.UTC).format(due);
            configure("org.tinysep.alerts", Map.of("contacts", FIRST, "summaryTime", hhmm, "timeZone", "UTC"));
            // DS puts the configuration on the service: the component with the new one is there
            AlertService alerts = awaitService(AlertService.class, "(summaryTime=" + hhmm + ")", TIMEOUT);
            f.alerts = alerts;
            f.collapse(); // an open alert for the summary to name
            f.sync.tickDone(due.minusSeconds(1));
            assertFalse("no summary before its time", events().contains("daily summary sent"));
            f.sync.tickDone(due);
            assertTrue("summary at its time", events().contains("daily summary sent to the Mail Manager's recipients:"
                    + " 1 open alert(s)"));
            await(TIMEOUT, () -> f.sink.messages().stream().anyMatch(m -> unfolded(m.data())
                    .startsWith("TinySEP is running")), "the summary mailed");
            SmtpSink.Received s = f.sink.messages().stream().filter(m -> unfolded(m.data())
                    .startsWith("TinySEP is running")).findFirst().orElseThrow();
            assertEquals(List.of(CARER), s.to());
            String body = s.body();
            assertTrue(body, body.contains("Open alerts: 1") && body.contains("Devices offline or failing:")
                    && body.contains("State folder") && body.contains("free on its disk"));
            f.sync.tickDone(due.plusSeconds(3600));
            assertEquals("once a day", 1, f.sink.messages().stream().filter(m -> unfolded(m.data())
                    .startsWith("TinySEP is running")).count());
            assertEquals(1, alerts.open().size());
        }
    }

    private static void assertStep(Alert a, int index, NotificationStep step, List<String> to) {
        assertTrue(a.notifications().toString(), a.notifications().size() > index);
        assertEquals(a.notifications().toString(), step, a.notifications().get(index).step());
        assertEquals(to, a.notifications().get(index).to());
    }

    private String events() {
        EventLog log = awaitService(EventLog.class, null, TIMEOUT);
        StringBuilder b = new StringBuilder();
        log.recent(2000).forEach(e -> b.append(e.origin()).append(": ").append(e.message()).append('\n'));
        return b.toString();
    }

    private String shellFails(String command) {
        try {
            return "did not fail: " + shell(command);
        } catch (AssertionError e) {
            return e.getMessage();
        }
    }
}

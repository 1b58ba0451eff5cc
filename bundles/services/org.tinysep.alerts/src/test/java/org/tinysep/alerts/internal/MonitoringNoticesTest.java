package org.tinysep.alerts.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.device.Connection;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.MailManagerListener;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;

/** The notice path of issue 25 (items 3 and 7): signals in the event log become one caregiver mail per cause. */
class MonitoringNoticesTest {

    private static final String DISABLED = "Monitoring reduced: Inactivity Recognition (org.tinysep.inactivity) was "
            + "stopped: nobody is told if the person stops moving";

    @TempDir
    Path dir;
    private final Log log = new Log();
    private final Mail mail = new Mail();

    private MonitoringNotices notices(long last) {
        return new MonitoringNotices(new NoticeFeed(last, Duration.ofMinutes(30)), new NoticeText(ZoneOffset.UTC),
                dir.resolve("notices.properties"));
    }

    @Test
    void aMonitoringReducedEntryBecomesOneNoticeMailInPlainWords() {
        MonitoringNotices n = notices(0);
        log.record(EventKind.PROBLEM, "radio", "the AmICA radio cannot listen"); // a problem, not a signal
        log.record(EventKind.PROBLEM, "drivers-list", DISABLED);
        n.poll(log, mail);
        assertEquals(1, mail.sent.size(), mail.sent.toString());
        String[] m = mail.sent.get(0);
        assertTrue(m[0].startsWith("TinySEP watches less than it should: Inactivity Recognition"), m[0]);
        assertTrue(m[1].contains("nobody is told if the person stops moving") && m[1].contains("What to do:")
                && m[1].contains("since 2026-11-28"), m[1]);
        assertTrue(log.entries.stream().anyMatch(e -> e.message().startsWith("notice sent to the caregivers")));
        n.poll(log, mail);
        assertEquals(1, mail.sent.size(), "an entry is noticed once");
    }

    @Test
    void theSameCauseInABurstMailsOnceAndSeveralCausesShareOneMail() {
        MonitoringNotices n = notices(0);
        for (int i = 0; i < 5; i++) {
            log.record(EventKind.PROBLEM, "drivers-list", DISABLED);
        }
        log.record(EventKind.PROBLEM, "Bus 1", "Node type mismatch: node 1.40 said it is a pet collar");
        n.poll(log, mail);
        log.record(EventKind.PROBLEM, "drivers-list", DISABLED);
        n.poll(log, mail);
        assertEquals(1, mail.sent.size(), mail.sent.toString());
        assertTrue(mail.sent.get(0)[0].endsWith("(and 1 more)"), mail.sent.get(0)[0]);
        assertTrue(mail.sent.get(0)[1].contains("node 1.40 said it is a pet collar"));
        log.later(Duration.ofMinutes(31));
        log.record(EventKind.PROBLEM, "drivers-list", DISABLED);
        n.poll(log, mail);
        assertEquals(2, mail.sent.size(), "after the quiet period the same cause is told again");
    }

    @Test
    void withoutAMailManagerTheSignalsWaitAndARestartDoesNotRepeatThem() {
        MonitoringNotices n = notices(0);
        log.record(EventKind.PROBLEM, "drivers-list", DISABLED);
        n.poll(log, null);
        n.poll(log, mail);
        assertEquals(1, mail.sent.size());
        MonitoringNotices again = notices(MonitoringNotices.load(dir.resolve("notices.properties")));
        again.poll(log, mail);
        assertEquals(1, mail.sent.size(), "the last entry handled is saved");
    }

    /** Device support's words (LostSources) when a watcher loses a sensor, and when it is back. */
    private static final String LOST = "Monitoring reduced: Inactivity recognition can no longer see the Bathroom: "
            + "its sensor \"Bathroom movement\" (m-1) went away at 2026-11-28 03:00:00 UTC; activity in the Bathroom "
            + "is not noticed until the sensor is back. Check the sensor and its radio node (tinysep:devices lists "
            + "them); an open alert stays open.";
    private static final String BACK = "monitoring restored: the sensor \"Bathroom movement\" in the Bathroom is "
            + "back and watched again";

    private Instant wall = Instant.parse("2026-11-28T03:00:00Z");

    private MonitoringNotices withGrace(Duration grace) {
        return new MonitoringNotices(new NoticeFeed(0, Duration.ofMinutes(30)), new NoticeText(ZoneOffset.UTC),
                dir.resolve("notices.properties"), grace, () -> wall);
    }

    @Test
    void aSensorBackWithinTheGraceMailsNothing() {
        MonitoringNotices n = withGrace(Duration.ofSeconds(60));
        log.record(EventKind.PROBLEM, "inactivity", LOST);
        n.poll(log, mail);
        assertEquals(0, mail.sent.size(), "held for the grace");
        wall = wall.plusSeconds(20);
        log.record(EventKind.DEVICE_EVENT, "inactivity", BACK);
        n.poll(log, mail);
        wall = wall.plusSeconds(120);
        n.poll(log, mail);
        assertEquals(0, mail.sent.size(), "the sensor came back within 60 s: " + mail.sent);
    }

    @Test
    void aSensorStillAwayAfterTheGraceIsMailedAndOtherSignalsAreNotHeld() {
        MonitoringNotices n = withGrace(Duration.ofSeconds(60));
        log.record(EventKind.PROBLEM, "inactivity", LOST);
        log.record(EventKind.DEVICE_EVENT, "flat-occupancy", BACK); // another watcher's sensor: not this one's
        log.record(EventKind.PROBLEM, "drivers-list", DISABLED);
        n.poll(log, mail);
        assertEquals(1, mail.sent.size(), "a signal about no sensor goes at once");
        assertTrue(mail.sent.get(0)[0].contains("Inactivity Recognition"), mail.sent.get(0)[0]);
        wall = wall.plusSeconds(59);
        n.poll(log, mail);
        assertEquals(1, mail.sent.size(), "still within the grace");
        wall = wall.plusSeconds(1);
        n.poll(log, mail);
        assertEquals(2, mail.sent.size(), "the sensor stayed away for the grace");
        assertTrue(mail.sent.get(1)[1].contains("can no longer see the Bathroom"), mail.sent.get(1)[1]);
    }

    @Test
    void aLookAtALogWithNothingNewCopiesOneEntryYetAHeldNoticeIsStillMailedWhenItsGraceEnds() {
        MonitoringNotices n = withGrace(Duration.ofSeconds(60));
        for (int i = 0; i < 400; i++) {
            log.record(EventKind.DEVICE_EVENT, "movement", "movement detected");
        }
        n.poll(log, mail);
        long before = log.copied;
        for (int i = 0; i < 100; i++) { // 200 s of an idle platform's looks
            n.poll(log, mail);
        }
        assertEquals(100, log.copied - before, "entries copied by 100 looks at a log with nothing new");
        log.record(EventKind.PROBLEM, "inactivity", LOST);
        n.poll(log, mail);
        assertEquals(0, mail.sent.size(), "held for the grace");
        wall = wall.plusSeconds(61);
        n.poll(log, mail); // nothing new in the log, but a notice waits for its grace
        assertEquals(1, mail.sent.size(), "the sensor stayed away for the grace: " + mail.sent);
        before = log.copied;
        n.poll(log, mail); // the "notice sent" entry is new once
        n.poll(log, mail);
        assertTrue(log.copied - before <= 503, "copied after the notice: " + (log.copied - before));
    }

    @Test
    void aGraceOfZeroMailsAtOnce() {
        MonitoringNotices n = withGrace(Duration.ZERO);
        log.record(EventKind.PROBLEM, "inactivity", LOST);
        n.poll(log, mail);
        assertEquals(1, mail.sent.size());
    }

    private static final class Log implements EventLog {
        final List<EventEntry> entries = new ArrayList<>();
        Instant now = Instant.parse("2026-11-28T03:00:00Z");

        void later(Duration d) {
            now = now.plus(d);
        }

        @Override
        public void record(EventKind kind, String origin, String message) {
            entries.add(new EventEntry(entries.size() + 1, now, kind, origin, message));
        }

        long copied; // entries handed out by recent(): what a look at the log costs

        @Override
        public List<EventEntry> recent(int max) {
            List<EventEntry> out = List.copyOf(entries.subList(Math.max(0, entries.size() - max), entries.size()));
            copied += out.size();
            return out;
        }
    }

    private static final class Mail implements MailManagerProvider {
        final List<String[]> sent = new ArrayList<>();

        @Override
        public void send(String subject, String body) {
            sent.add(new String[] {subject, body});
        }

        @Override
        public MailStatus status() {
            return null;
        }

        @Override
        public String deviceUid() {
            return "mail";
        }

        @Override
        public Connection connect(MailManagerListener listener) {
            throw new UnsupportedOperationException();
        }
    }
}

package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.PersonWatch;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.inactivity.internal.person.WearerSettings;

/**
 * README "Activity per person", "Known limits" lifted: each wearer's watch is in the device's backup (last movement,
 * where last seen, worn, the watch's last activity and start, the alert handed on), so after a restart the wearer's
 * quiet time keeps counting and the alert comes at the original deadline, not the restart's.
 */
class PerPersonRestartTest {

    private static final Instant T0 = Instant.parse("2026-11-29T10:00:00Z");
    private Instant now = T0;
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final Fakes.Directory directory = new Fakes.Directory();

    /** One run of the platform: the device and the providers it is connected to. */
    private final class Run {
        final InactivityDevice device = new InactivityDevice(
                new DriverContext(null, "d", "InactivityRecognition", logs.reporter(), new PlatformClock(() -> now)),
                directory, LimitTable.parse(120, "Kitchen=90", ""), new AlertMail(ZoneOffset.UTC));
        final Fakes.Movement kitchen = new Fakes.Movement("m-kitchen");
        final Fakes.Mail mail = new Fakes.Mail("mail");
        final PerPersonDeviceTest.Node anna = new PerPersonDeviceTest.Node("node-anna", "Anna");
        final PerPersonDeviceTest.Node bert = new PerPersonDeviceTest.Node("node-bert", "Bert");

        /** As the driver makes it: settings, then the backup (if any), then its connections. */
        Run(ComponentBackup saved, boolean withBert) {
            device.watchPersons(WearerSettings.defaults(), ZoneOffset.UTC, new HelpCall.AlertDesk() {
                @Override
                public <T> Optional<T> use(java.util.function.Function<org.tinysep.api.alert.AlertService, T> use) {
                    return Optional.empty(); // no alert service: the Mail Manager takes the alerts
                }
            });
            if (saved != null) {
                device.onRestore(saved);
            }
            device.use(InactivityDeviceTest.house(new Room("r-k", "Kitchen", "Kitchen", Set.of())));
            device.watch(kitchen);
            device.use(mail);
            device.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, T0)); // Flat Occupancy restores its decision too
            device.use(anna);
            if (withBert) {
                device.use(bert);
            }
        }

        void until(Instant t) {
            while (now.isBefore(t)) {
                now = now.plusSeconds(1);
                device.tick(now);
            }
        }

        PersonWatch watch(String person) {
            return device.persons().stream().filter(p -> p.person().equals(person)).findFirst().orElseThrow();
        }

        /** Each minute: Anna's pendant still, Bert's moving, the kitchen sensor seeing him. */
        void bertBusyUntil(Instant end) {
            while (now.isBefore(end)) {
                until(now.plusSeconds(60));
                anna.summary(now, 3);
                bert.summary(now, 180);
                kitchen.report(true, now);
            }
        }
    }

    PerPersonRestartTest() {
        directory.rooms.put("m-kitchen", "r-k");
        directory.names.put("m-kitchen", "Kitchen sensor");
    }

    @Test
    void afterARestartTheWearersAlertComesAtTheOriginalDeadline() {
        Run before = new Run(null, true);
        before.anna.summary(now, 200); // 10:00 Anna moves alone in the kitchen: seen there, Kitchen's 90 min
        before.bert.summary(now, 3);
        before.kitchen.report(true, now);
        before.bertBusyUntil(T0.plus(Duration.ofMinutes(30)));
        assertEquals(Optional.of("Kitchen"), before.watch("Anna").lastRoom());
        ComponentBackup saved = before.device.backup(); // the last save, then the platform is killed (10:30)

        now = T0.plus(Duration.ofMinutes(35)); // restarted at 10:35
        Run after = new Run(saved, true);
        after.bertBusyUntil(T0.plus(Duration.ofMinutes(89)));
        after.until(T0.plus(Duration.ofMinutes(90)).minusSeconds(1));
        assertEquals(InactivityState.WATCHING, after.watch("Anna").state(), "before 10:00 + the Kitchen's 90 min");
        after.until(T0.plus(Duration.ofMinutes(90)));
        assertEquals(InactivityState.ALERT, after.watch("Anna").state(),
                "due at 10:00 + 90 min, not at the restart + a limit");
        assertEquals(InactivityState.WATCHING, after.watch("Bert").state());
        assertEquals(1, after.mail.sent.size(), after.mail.sent.toString());
        assertTrue(after.mail.sent.get(0).startsWith("TinySEP: Anna has not been active since 10:00 (last seen in "
                + "Kitchen)\n"), after.mail.sent.get(0));
    }

    @Test
    void whatComesBackIsShownAndSaidAtOnce() {
        Run before = new Run(null, true);
        before.anna.summary(now, 200);
        before.bert.summary(now, 3);
        before.kitchen.report(true, now);
        before.until(T0.plus(Duration.ofMinutes(10)));
        ComponentBackup saved = before.device.backup();

        now = T0.plus(Duration.ofMinutes(15));
        Run after = new Run(saved, true); // before any node is heard again
        PersonWatch restored = after.watch("Anna");
        assertEquals(Optional.of("Kitchen"), restored.lastRoom(), "where she was last seen comes back");
        assertEquals(T0, restored.lastMovement());
        assertTrue(restored.worn());
        assertEquals(InactivityState.WATCHING, restored.state());
        assertTrue(logs.events().stream().anyMatch(e -> e.message().startsWith("restored after a restart: Anna's "
                + "watch: last active at 10:00 (") && e.message().endsWith("), last seen in Kitchen, pendant worn, "
                + "still since 10:00; the quiet time keeps counting")), logs.events().toString());
    }

    @Test
    void anAlertHandedOnBeforeTheRestartIsNotHandedOnAgain() {
        Run before = new Run(null, false);
        before.anna.summary(now, 200);
        before.kitchen.report(true, now);
        before.until(T0.plus(Duration.ofMinutes(91)));
        assertEquals(InactivityState.ALERT, before.watch("Anna").state());
        assertEquals(1, before.mail.sent.size());
        ComponentBackup saved = before.device.backup();

        now = T0.plus(Duration.ofMinutes(95));
        Run after = new Run(saved, false);
        after.until(now.plusSeconds(2));
        assertEquals(InactivityState.ALERT, after.watch("Anna").state(), "still raised: she is still quiet");
        assertEquals(List.of(), after.mail.sent, "handed on once, before the restart");
        after.anna.summary(now, 150);
        assertEquals(InactivityState.WATCHING, after.watch("Anna").state(), "her pendant moved: cleared");
    }

    @Test
    void aPendantThatSeemedNotWornStaysSoAfterTheRestart() {
        Run before = new Run(null, false);
        before.anna.summary(now, 150);
        before.kitchen.report(true, now);
        for (int m = 20; m <= 140; m += 20) { // the pendant lies still while the kitchen sees someone
            before.until(T0.plus(Duration.ofMinutes(m)));
            before.anna.summary(now, 2);
            before.kitchen.report(true, now);
        }
        assertFalse(before.watch("Anna").worn());
        ComponentBackup saved = before.device.backup();

        now = T0.plus(Duration.ofMinutes(150));
        Run after = new Run(saved, false);
        assertFalse(after.watch("Anna").worn(), "not worn comes back");
        assertEquals(T0, after.watch("Anna").lastMovement());
        after.anna.summary(now, 2);
        after.kitchen.report(true, now);
        assertEquals(1, logs.events().stream().filter(e -> e.message().startsWith("Anna's pendant seems not to be "
                + "worn")).count(), "said once, not again after the restart: " + logs.events());
        after.anna.summary(now, 120);
        assertTrue(after.watch("Anna").worn());
    }

    @Test
    void anUnreadableSavedWearerIsSkippedWithAProblemAndTheRestRestored() {
        Run before = new Run(null, true);
        before.anna.summary(now, 200);
        before.bert.summary(now, 3);
        before.kitchen.report(true, now);
        ComponentBackup good = before.device.backup();
        java.util.Map<String, String> state = new java.util.LinkedHashMap<>(good.state());
        String bert = state.entrySet().stream().filter(e -> e.getValue().equals("node-bert")).findFirst()
                .orElseThrow().getKey().replace(".node", ".");
        state.put(bert + "lastMovement", "yesterday");
        ComponentBackup bad = new ComponentBackup(good.uid(), good.kind(), good.driverUid(), good.driverName(),
                good.type(), good.name(), good.parameters(), good.nodeAddress(), good.nodeTypes(), good.lastSeen(),
                state, good.savedAt());
        now = now.plusSeconds(60);
        Run after = new Run(bad, true);
        assertEquals(Optional.of("Kitchen"), after.watch("Anna").lastRoom());
        assertTrue(after.device.persons().stream().noneMatch(p -> p.person().equals("Bert")),
                "Bert's watch begins again with his node's next summary");
        assertTrue(logs.events().stream().anyMatch(e -> e.message().startsWith("saved watch of node-bert not "
                + "restored")), logs.events().toString());
    }
}

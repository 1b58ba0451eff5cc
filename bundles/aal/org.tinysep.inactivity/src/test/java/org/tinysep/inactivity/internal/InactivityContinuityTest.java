package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Issue 10 items 1 and 2 with a fake clock: the clock going back (virtual time, then real time; a backup from the
 * future) never makes fresh activity be ignored; a restart resumes the quiet time that began before it, and an
 * alert that fell due while nothing ran is raised at once and says it is late.
 */
class InactivityContinuityTest {

    private static final Instant T0 = Instant.parse("2026-11-22T09:00:00Z");
    private static final Instant FUTURE = Instant.parse("2099-01-01T00:00:00Z");

    private Instant now = T0;
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final Fakes.Directory directory = new Fakes.Directory();
    private final Fakes.Movement bathSensor = new Fakes.Movement("m-bath");
    private final Fakes.Mail mail = new Fakes.Mail("mail");

    InactivityContinuityTest() {
        directory.rooms.put("m-bath", "r-bath");
        directory.names.put("m-bath", "Bath sensor");
    }

    /** A device as the driver makes it (after a restart: restored from {@code saved} before it connects). */
    private InactivityDevice device(ComponentBackup saved, Fakes.Flat flat) {
        InactivityDevice d = new InactivityDevice(
                new DriverContext(null, "d", "InactivityRecognition", logs.reporter(), new PlatformClock(() -> now)),
                directory, LimitTable.parse(120, "Bathroom=45", ""), new AlertMail(ZoneOffset.UTC));
        if (saved != null) {
            d.onRestore(saved);
        }
        d.use(InactivityDeviceTest.house(new Room("r-bath", "Bathroom", "Bathroom", Set.of())));
        d.watch(bathSensor);
        d.use(mail);
        d.use(flat);
        return d;
    }

    private void tickUntil(InactivityDevice d, Instant until) {
        while (now.isBefore(until)) {
            now = now.plusSeconds(1);
            d.tick(now);
        }
    }

    private static String parameter(InactivityDevice d, String key) {
        return d.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).map(String::valueOf)
                .findFirst().orElseThrow();
    }

    private boolean logged(String text) {
        return logs.events().stream().anyMatch(e -> e.message().contains(text));
    }

    @Test
    void timeJumpForwardsThenBackNeverIgnoresFreshActivity() {
        InactivityDevice d = device(null, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        bathSensor.report(true, now);
        now = FUTURE; // a synchroniser (or the demo) played a later day
        bathSensor.report(true, now);
        d.tick(now);
        assertEquals(FUTURE.plusSeconds(45 * 60).toString(), parameter(d, "deadline"));

        now = T0.plusSeconds(3600); // back to real time
        d.tick(now);
        assertEquals(now.plusSeconds(45 * 60).toString(), parameter(d, "deadline"),
                "the quiet time is counted from when the clock came back, not from 2099");
        assertTrue(logged("clock went back from 2099-01-01 00:00:00 Z to 2026-11-22 10:00:00 Z: quiet time in "
                + "Bathroom counted from now"), logs.events().toString());

        now = now.plusSeconds(600);
        Instant moved = now;
        bathSensor.report(true, moved);
        assertTrue(parameter(d, "lastActivity").endsWith(" at " + moved), "fresh activity counts: "
                + parameter(d, "lastActivity"));
        assertEquals(moved.plusSeconds(45 * 60).toString(), parameter(d, "deadline"));
        tickUntil(d, moved.plusSeconds(45 * 60));
        assertEquals(InactivityState.ALERT, d.state());
        assertEquals(moved, d.alert().orElseThrow().lastActivityAt());
        assertEquals(1, mail.sent.size());
    }

    @Test
    void anActivityFromTheFutureDoesNotHideTheNextOneEvenWithoutATickBetween() {
        InactivityDevice d = device(null, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        bathSensor.report(true, FUTURE);
        now = T0.plusSeconds(60);
        bathSensor.report(true, now);
        assertEquals(now.plusSeconds(45 * 60).toString(), parameter(d, "deadline"));
    }

    @Test
    void aBackupFromTheFutureIsCountedFromNow() {
        InactivityDevice before = device(null, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        now = FUTURE;
        bathSensor.report(true, now);
        before.tick(now);
        ComponentBackup saved = before.backup();

        now = T0.plusSeconds(3600); // restarted in real time
        InactivityDevice after = device(saved, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        after.tick(now.plusSeconds(1));
        assertEquals(now.plusSeconds(45 * 60).toString(), parameter(after, "deadline"),
                "restored, but not as if 2099 were valid");
        assertTrue(logged("saved state from the future"), logs.events().toString());
    }

    @Test
    void killedWithThePersonAlreadyQuietTheAlertComesAtTheRightTimeAfterTheRestart() {
        InactivityDevice before = device(null, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        tickUntil(before, T0.plusSeconds(600));
        bathSensor.report(true, now); // 09:10 in the bathroom, then nothing
        tickUntil(before, T0.plusSeconds(600 + 10 * 60));
        ComponentBackup saved = before.backup(); // the last save before the kill (09:20)

        now = T0.plusSeconds(600 + 15 * 60); // restarted at 09:25, flat occupancy restored
        InactivityDevice after = device(saved, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        bathSensor.report(false, now); // the node's first report after the restart: no motion
        tickUntil(after, T0.plusSeconds(600 + 45 * 60 - 1));
        assertEquals(InactivityState.WATCHING, after.state());
        tickUntil(after, T0.plusSeconds(600 + 45 * 60));
        assertEquals(InactivityState.ALERT, after.state(), "due at 09:10 + 45 min, not at the restart + 45 min");
        assertEquals(List.of("TinySEP: no activity in Bathroom since 09:10"), subjects());
    }

    @Test
    void anAlertDueDuringTheOutageIsRaisedAtOnceAndSaysItIsLate() {
        InactivityDevice before = device(null, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        tickUntil(before, T0.plusSeconds(600));
        bathSensor.report(true, now); // 09:10
        tickUntil(before, T0.plusSeconds(1200));
        ComponentBackup saved = before.backup(); // 09:20, then the platform is killed

        now = T0.plusSeconds(4200); // 10:10: restarted 50 min later
        InactivityDevice after = device(saved, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        bathSensor.report(false, now);
        after.tick(now.plusSeconds(1));
        assertEquals(InactivityState.ALERT, after.state(), "due at 09:55 during the outage: raised at once");
        assertEquals(T0.plusSeconds(600), after.alert().orElseThrow().lastActivityAt());
        assertEquals(List.of("TinySEP: no activity in Bathroom since 09:10 (Inactivity Recognition was not running "
                + "from 09:20 to 10:10; this alert is late)"), subjects());
        assertTrue(mail.sent.get(0).contains("It fell due at 2026-11-22 09:55:00 Z"), mail.sent.get(0));
        assertTrue(logged("alert handed to the Mail Manager"), logs.events().toString());
        assertTrue(logged("restored after a restart: last activity movement by Bath sensor (before restart) in "
                + "Bathroom at 2026-11-22 09:10:00 Z"), logs.events().toString());
    }

    @Test
    void anAlertHandedOverBeforeTheRestartIsNotHandedOverAgain() {
        InactivityDevice before = device(null, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        bathSensor.report(true, T0);
        tickUntil(before, T0.plusSeconds(46 * 60));
        assertEquals(1, mail.sent.size());
        ComponentBackup saved = before.backup();

        now = now.plusSeconds(600);
        InactivityDevice after = device(saved, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        after.tick(now.plusSeconds(1));
        assertEquals(InactivityState.ALERT, after.state(), "still raised after the restart");
        assertEquals(1, mail.sent.size(), "but not mailed twice");
    }

    @Test
    void anOrderlyStopWhereFlatOccupancyGoesFirstStillResumesTheCount() {
        Fakes.Flat flat = new Fakes.Flat("flat", Occupancy.OCCUPIED, T0);
        InactivityDevice before = device(null, flat);
        tickUntil(before, T0.plusSeconds(600));
        bathSensor.report(true, now); // 09:10
        tickUntil(before, T0.plusSeconds(900));
        before.forget("flat"); // the platform stops: Flat Occupancy's service goes before this device is disposed
        assertEquals(InactivityState.NOT_WATCHING, before.state());
        ComponentBackup saved = before.backup();

        now = T0.plusSeconds(1200);
        InactivityDevice after = device(saved, new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        assertEquals(T0.plusSeconds(600 + 45 * 60).toString(), parameter(after, "deadline"), "09:10 + 45 min");

        flat.change(Occupancy.UNOCCUPIED, now); // someone left: that ends the count for good
        assertEquals("", before.backupState().getOrDefault("watching.from", ""));
    }

    private List<String> subjects() {
        return mail.sent.stream().map(m -> m.substring(0, m.indexOf('\n'))).toList();
    }
}

package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.sensor.person.PersonNodeListener;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.PersonWatch;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.inactivity.internal.person.WearerSettings;

/** The device with person nodes (README "Activity per person"): each wearer watched on their own. */
class PerPersonDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-29T10:00:00Z");
    private Instant now = T0;
    private final RecordingLogs logs = new RecordingLogs(() -> now);
    private final Fakes.Directory directory = new Fakes.Directory();
    private final InactivityDevice device = new InactivityDevice(
            new DriverContext(null, "d", "InactivityRecognition", logs.reporter(), new PlatformClock(() -> now)),
            directory, LimitTable.parse(120, "Kitchen=90", ""), new AlertMail(ZoneOffset.UTC));
    private final Fakes.Movement kitchen = new Fakes.Movement("m-kitchen");
    private final Fakes.Mail mail = new Fakes.Mail("mail");
    private final Node anna = new Node("node-anna", "Anna");
    private final Node bert = new Node("node-bert", "Bert");

    /** A person node: its wearer's name and its summaries. */
    static final class Node extends Fakes.Base<PersonNodeListener> implements PersonNodeProvider {
        final String person;

        Node(String uid, String person) {
            super(uid);
            this.person = person;
        }

        void summary(Instant end, int sdMg) {
            MovementSummary s = new MovementSummary(end, Duration.ofSeconds(2), new Acceleration(0, -1000, 0), sdMg,
                    1000 + sdMg);
            List.copyOf(listeners).forEach(l -> l.movementSummarised(this, s));
        }

        @Override
        public Optional<String> person() {
            return Optional.of(person);
        }

        @Override
        public Optional<MovementSummary> lastSummary() {
            return Optional.empty();
        }
    }

    PerPersonDeviceTest() {
        directory.rooms.put("m-kitchen", "r-k");
        directory.names.put("m-kitchen", "Kitchen sensor");
        device.watchPersons(WearerSettings.defaults(), ZoneOffset.UTC, new HelpCall.AlertDesk() {
            @Override
            public <T> Optional<T> use(java.util.function.Function<org.tinysep.api.alert.AlertService, T> use) {
                return Optional.empty(); // no alert service: the Mail Manager takes the alerts
            }
        });
        device.use(InactivityDeviceTest.house(new Room("r-k", "Kitchen", "Kitchen", Set.of())));
        device.watch(kitchen);
        device.use(mail);
        device.use(new Fakes.Flat("flat", Occupancy.OCCUPIED, T0));
        device.use(anna);
        device.use(bert);
    }

    private void at(Instant t) {
        while (now.isBefore(t)) {
            now = now.plusSeconds(1);
            device.tick(now);
        }
    }

    private List<String> events() {
        return logs.events().stream().map(e -> e.message()).toList();
    }

    private PersonWatch watch(String person) {
        return device.persons().stream().filter(p -> p.person().equals(person)).findFirst().orElseThrow();
    }

    @Test
    void annaStillWhileBertMovesAndTheKitchenIsBusyIsAlertedByName() {
        anna.summary(now, 200); // both move in the kitchen at 10:00
        bert.summary(now, 200);
        kitchen.report(true, now);
        at(T0.plusSeconds(10));
        anna.summary(now, 150); // Anna's last movement, alone: she is seen in the kitchen
        kitchen.report(true, now);
        Instant annaStill = now;
        for (int m = 1; m <= 100; m++) { // Bert keeps moving and the kitchen sensor keeps seeing him
            at(annaStill.plus(Duration.ofMinutes(m)));
            anna.summary(now, 3);
            bert.summary(now, 180);
            kitchen.report(true, now);
            if (m == 89) {
                assertEquals(InactivityState.WATCHING, watch("Anna").state(), "before Kitchen's 90 min");
            }
        }
        assertEquals(InactivityState.ALERT, watch("Anna").state());
        assertEquals(InactivityState.WATCHING, watch("Bert").state());
        assertEquals(InactivityState.WATCHING, device.state(), "the flat is busy");
        assertEquals(Optional.of("Kitchen"), watch("Anna").lastRoom());
        assertTrue(watch("Anna").worn(), "Bert explained the room activity: no reason to doubt the pendant");
        assertEquals(1, mail.sent.size(), mail.sent.toString());
        String m = mail.sent.get(0);
        assertTrue(m.startsWith("TinySEP: Anna has not been active since 10:00 (last seen in Kitchen)\n"), m);
        assertTrue(m.contains("Pendant: has been still since 10:00 (1 h 30 min)"), m);
        assertTrue(m.contains("Meanwhile the room sensors saw activity 89 times, each while the node of Bert was "
                + "moving, so it was not counted as Anna's."), m);
        assertTrue(events().stream().anyMatch(e -> e.startsWith("inactivity alert for Anna (limit reached): TinySEP: "
                + "Anna has not been active since 10:00 (last seen in Kitchen); Anna's pendant has been still since "
                + "10:00 (1 h 30 min)")), events().toString());

        anna.summary(now, 90);
        assertEquals(InactivityState.WATCHING, watch("Anna").state(), "her pendant moved: cleared");
        assertTrue(events().stream().anyMatch(e -> e.startsWith("inactivity watching for Anna (Anna's pendant moved")));
    }

    @Test
    void onePersonsPendantStillWhileTheKitchenSeesSomeoneIsNotWornNotAnAlarm() {
        device.forget("node-bert");
        anna.summary(now, 150);
        kitchen.report(true, now);
        for (int m = 20; m <= 180; m += 20) {
            at(T0.plus(Duration.ofMinutes(m)));
            anna.summary(now, 2);
            kitchen.report(true, now);
        }
        assertEquals(List.of(), mail.sent, "no alert");
        assertEquals(InactivityState.WATCHING, watch("Anna").state());
        assertEquals(false, watch("Anna").worn());
        assertEquals(1, events().stream().filter(e -> e.equals("Anna's pendant seems not to be worn: it has not "
                + "moved since 10:00 while the sensors saw someone in the Kitchen; until it moves again, Anna is "
                + "watched by the room sensors")).count(), events().toString());
        anna.summary(now, 120);
        assertTrue(watch("Anna").worn());
        assertTrue(events().contains("Anna's pendant is worn again: it moved at 13:00; its movement counts as Anna's "
                + "activity again"), events().toString());
    }

    @Test
    void withAWearerTheFlatsOwnAlertIsLeftToThePersonsWatch() {
        device.forget("node-bert");
        anna.summary(now, 150);
        kitchen.report(true, now);
        at(T0.plus(Duration.ofMinutes(91)));
        assertEquals(InactivityState.ALERT, device.state());
        assertEquals(InactivityState.ALERT, watch("Anna").state());
        assertEquals(1, mail.sent.size(), "one alert, Anna's: " + mail.sent);
        assertTrue(mail.sent.get(0).startsWith("TinySEP: Anna has not been active since 10:00"), mail.sent.get(0));
        assertTrue(events().stream().anyMatch(e -> e.startsWith("the flat's inactivity alert is not handed on: Anna "
                + "wears a person node")), events().toString());
    }
}

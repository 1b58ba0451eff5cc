package org.tinysep.helpbutton.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.annotation.Annotation;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.sensor.person.ButtonAction;
import org.tinysep.api.sensor.person.ButtonEvent;

class HelpCallsTest {

    private static final Instant T0 = Instant.parse("2026-11-29T14:02:00Z");
    private static final HelpCalls.Node ANNA = new HelpCalls.Node("dev-1", "0014.4F01.0000.A001",
            () -> Optional.of("Anna"));
    private static final HelpCalls.Node NOBODY = new HelpCalls.Node("dev-2", "0014.4F01.0000.A002", Optional::empty);

    private final List<AlertRequest> raised = new ArrayList<>();
    private final List<String> cleared = new ArrayList<>();
    private final List<String> events = new ArrayList<>();
    private boolean serviceRuns = true;

    private final HelpCalls calls = new HelpCalls(new HelpCalls.Desk() {
        @Override
        public Optional<Alert> raise(AlertRequest r) {
            if (!serviceRuns) {
                return Optional.empty();
            }
            raised.add(r);
            return Optional.of(new Alert(String.valueOf(raised.size()), r.kind(), r.source(), "", "", r.raisedAt(),
                    r.subject(), r.text(), AlertState.OPEN, 1, null, "", List.of()));
        }

        @Override
        public Optional<Integer> clear(String source, String why) {
            cleared.add(source + " | " + why);
            return serviceRuns ? Optional.of(1) : Optional.empty();
        }
    }, events::add);

    HelpCallsTest() {
        calls.settings(new HelpSettings(Duration.ofSeconds(1), Duration.ofSeconds(10), 0, ZoneOffset.UTC));
    }

    private void press(HelpCalls.Node node, int button, long millis) {
        calls.button(node, new ButtonEvent(button, ButtonAction.PRESSED, T0.plusMillis(millis)));
    }

    private void release(HelpCalls.Node node, int button, long millis) {
        calls.button(node, new ButtonEvent(button, ButtonAction.RELEASED, T0.plusMillis(millis)));
    }

    @Test
    void holdingTheSwitchForASecondRaisesAHelpAlertAtTheRelease() {
        press(ANNA, 1, 0);
        release(ANNA, 1, 1200);

        assertEquals(1, raised.size());
        AlertRequest r = raised.get(0);
        assertEquals(AlertKind.HELP, r.kind());
        assertEquals("help:0014.4F01.0000.A001", r.source());
        assertEquals(T0.plusMillis(1200), r.raisedAt());
        assertEquals("TinySEP: Anna asks for help (help button, 14:02:01)", r.subject());
        assertTrue(r.text().startsWith("Anna held switch 1 of the person node 0014.4F01.0000.A001 (held for 1.2 s, "
                + "at 14:02:01): a call for help."), r.text());
        assertTrue(r.text().contains("a second press within 10.0 s cancels the call"), r.text());
        assertEquals(List.of("help call from Anna at 14:02:01 (switch 1 held for 1.2 s): raised as alert 1 through "
                + "the alert service; a second press by 14:02:11 cancels it"), events);
    }

    @Test
    void aShortPressIsLoggedAndRaisesNothing() {
        press(NOBODY, 2, 0);
        release(NOBODY, 2, 400);
        calls.tick(T0.plusSeconds(5));
        assertEquals(List.of(), raised);
        assertEquals(List.of("the wearer of person node 0014.4F01.0000.A002 pressed switch 2 for only 0.4 s: not a "
                + "help call (the switch must be held for at least 1.0 s)"), events);
    }

    @Test
    void aSwitchStillHeldIsACallAtTheTickThatFindsItAndOnlyOnce() {
        press(ANNA, 1, 300);
        calls.tick(T0.plusSeconds(1));
        assertEquals(List.of(), raised, "held 0.7 s");
        calls.tick(T0.plusSeconds(2));
        assertEquals(1, raised.size());
        assertEquals(T0.plusSeconds(2), raised.get(0).raisedAt());
        assertTrue(events.get(0).contains("switch 1 still held after 1.7 s"), events.get(0));
        calls.tick(T0.plusSeconds(3));
        release(ANNA, 1, 4000);
        assertEquals(1, raised.size(), "one call per press");
    }

    @Test
    void aSecondPressWithinTheWindowCancelsAsPressedByMistake() {
        press(ANNA, 1, 0);
        release(ANNA, 1, 1500);
        press(ANNA, 1, 6000);
        release(ANNA, 1, 8500); // the cancel press, however long, calls nothing
        calls.tick(T0.plusSeconds(9));

        assertEquals(1, raised.size());
        assertEquals(List.of("help:0014.4F01.0000.A001 | pressed by mistake: Anna pressed the switch again at "
                + "14:02:06, 4.5 s after the help call"), cleared);
        assertEquals("help call from Anna of 14:02:01 cancelled, pressed by mistake: Anna pressed the switch again "
                + "at 14:02:06, 4.5 s after the help call; everyone told gets an all clear", events.get(1));

        press(ANNA, 1, 20_000); // a new call later
        release(ANNA, 1, 21_000);
        assertEquals(2, raised.size());
    }

    @Test
    void aPressAfterTheWindowIsNotACancelButMayBeANewCall() {
        press(ANNA, 1, 0);
        release(ANNA, 1, 1000);
        press(ANNA, 1, 11_001);
        release(ANNA, 1, 11_200);
        assertEquals(List.of(), cleared);
        assertEquals(1, raised.size());
    }

    @Test
    void withoutAnAlertServiceTheLogSaysNobodyWasTold() {
        serviceRuns = false;
        press(ANNA, 1, 0);
        release(ANNA, 1, 2000);
        assertEquals(List.of("help call from Anna at 14:02:02 (switch 1 held for 2.0 s) could not be raised: no alert "
                + "service is running (bundle org.tinysep.alerts), nobody was told"), events);
    }

    @Test
    void onlyTheConfiguredSwitchCounts() {
        calls.settings(new HelpSettings(Duration.ofSeconds(1), Duration.ZERO, 2, ZoneOffset.UTC));
        press(ANNA, 1, 0);
        release(ANNA, 1, 3000);
        assertEquals(List.of(), raised);
        press(ANNA, 2, 4000);
        release(ANNA, 2, 5000);
        press(ANNA, 2, 6000); // no cancel window: not a cancel
        assertEquals(1, raised.size());
        assertEquals(List.of(), cleared);
    }

    @Test
    void badSettingsAreNamed() {
        assertEquals("holdMillis 50 is outside 100..10000", assertThrows(IllegalArgumentException.class,
                () -> HelpSettings.parse(config(50, 10, 0, ""))).getMessage());
        assertEquals("cancelSeconds -1 is outside 0..120", assertThrows(IllegalArgumentException.class,
                () -> HelpSettings.parse(config(1000, -1, 0, ""))).getMessage());
        assertEquals("button 3 is not 1, 2 or 0 (either)", assertThrows(IllegalArgumentException.class,
                () -> HelpSettings.parse(config(1000, 10, 3, ""))).getMessage());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HelpSettings.parse(config(1000, 10, 0,
                "Mars/Base"))).getMessage().startsWith("timeZone 'Mars/Base'"));
        assertEquals(Duration.ofMillis(1500), HelpSettings.parse(config(1500, 10, 0, "UTC")).hold());
    }

    private static HelpButtonConfig config(int hold, int cancel, int button, String zone) {
        return new HelpButtonConfig() {
            @Override
            public Class<? extends Annotation> annotationType() {
                return HelpButtonConfig.class;
            }

            @Override
            public int holdMillis() {
                return hold;
            }

            @Override
            public int cancelSeconds() {
                return cancel;
            }

            @Override
            public int button() {
                return button;
            }

            @Override
            public String timeZone() {
                return zone;
            }
        };
    }

    /** Issue 29, idle: the ticker calls the help button only while a switch is held, and a press says until when. */
    @Test
    void aTickIsNeededOnlyWhileASwitchIsHeldAndNotYetACall() {
        List<Instant> asked = new ArrayList<>();
        calls.whenDue(asked::add);
        assertEquals(null, calls.tick(T0), "no switch held: no tick needed");
        press(ANNA, 1, 300);
        assertEquals(List.of(T0.plusMillis(1300)), asked, "the press asks for a tick when it becomes a help call");
        assertEquals(T0.plusMillis(1300), calls.tick(T0.plusSeconds(1)), "held 0.7 s: not yet");
        assertEquals(null, calls.tick(T0.plusSeconds(2)), "called: no further tick needed for this press");
        assertEquals(1, raised.size());
    }
}

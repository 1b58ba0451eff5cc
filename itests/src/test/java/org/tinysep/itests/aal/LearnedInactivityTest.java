package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.api.device.Device;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * The LEARNED detector end to end in virtual time (issue 11): real AmICA movement nodes over UDP, Flat Occupancy,
 * House Information and the Mail Manager mailing a real SMTP server. With {@code learnMinDays=1} and
 * {@code learnMinPeriodsToShorten=1} (the default 30 keeps the fixed limits on thin history, issue 28) one day of
 * history is enough: a limit learned from it, shorter than the fixed one, alerts earlier and says why; a night
 * trip to the bathroom that does not end is alerted by the bathroom's night limit, not the night's.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class LearnedInactivityTest extends AalTestSupport {

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        return replacing(super.initialConfigurations(), "org.tinysep.inactivity",
                Map.of("timeZone", "UTC", "detector", "LEARNED", "learnMinDays", "1",
                        "learnMinPeriodsToShorten", "1"));
    }

    private SyncPeer sync;
    private InactivityRecognitionProvider inactivity;
    private Device device;

    /** The node reports motion at the platform's current (virtual) second; waits until Inactivity heard it. */
    private void motion(AmicaNode node, String room) throws Exception {
        String before = parameter(device, "lastActivity");
        node.motion(true);
        await(TIMEOUT, () -> !parameter(device, "lastActivity").equals(before)
                && parameter(device, "lastActivity").contains("in " + room), "movement in " + room);
        node.motion(false);
    }

    /** Advances virtual time to {@code at}, then {@link #motion(AmicaNode, String)}: one step of a scripted day. */
    private void motionAt(Instant at, AmicaNode node, String room) throws Exception {
        sync.tickDone(at);
        motion(node, room);
    }

    private void setUp() {
        inactivity = awaitService(InactivityRecognitionProvider.class, null, TIMEOUT);
        device = awaitService(Device.class, "(tinysep.device.uid=" + inactivity.deviceUid() + ")", TIMEOUT);
    }

    /** 00:00 of the day after tomorrow, virtual. */
    private Instant midnight() {
        return tomorrow().truncatedTo(ChronoUnit.DAYS).plus(Duration.ofDays(1));
    }

    @Test
    public void aLearnedLimitShorterThanTheFixedOneAlertsEarlierAndExplainsItself() throws Exception {
        try (SmtpSink sink = new SmtpSink().start(); SyncPeer s = sync(); AmicaNode bath = node(1, 41, MOVEMENT);
                AmicaNode kitchen = node(1, 42, MOVEMENT)) {
            sync = s;
            mailTo(sink, "carer@care.test");
            Instant day1 = midnight().plus(Duration.ofHours(14));
            sync.tickDone(day1);
            placeIn(bath, "AmicaMovement", "Bathroom");
            placeIn(kitchen, "AmicaMovement", "Kitchen");
            setUp();

            // day 1: 10 quiet minutes after the bathroom, at 14:00
            motion(bath, "Bathroom");
            motionAt(day1.plus(Duration.ofMinutes(10)), kitchen, "Kitchen");

            // day 2, 14:00: the bathroom, then nothing (a collapse)
            Instant day2 = day1.plus(Duration.ofDays(1));
            motionAt(day2, bath, "Bathroom");
            await(TIMEOUT, () -> inactivity.state() == InactivityState.WATCHING, "WATCHING");
            String reason = parameter(device, "limitReason");
            assertTrue(reason, reason.startsWith("usually at most 10 min between 13:00 and 16:00 in Bathroom, "
                    + "from 1 day (1 quiet period); limit 25 min"));

            sync.tickDone(day2.plus(Duration.ofMinutes(25)).minusSeconds(1));
            assertEquals(InactivityState.WATCHING, inactivity.state());
            sync.tickDone(day2.plus(Duration.ofMinutes(25)));
            assertEquals("learned 10 min x 1.5 + 10 min = 25 min, not the fixed 45 min", InactivityState.ALERT,
                    inactivity.state());
            InactivityAlert alert = inactivity.alert().orElseThrow();
            assertEquals("Bathroom", alert.roomName());
            assertTrue(alert.explanation(), alert.explanation().startsWith("usually at most 10 min"));
            await(TIMEOUT, () -> sink.messages().stream().anyMatch(m -> m.subject().contains("Bathroom since 14:00")),
                    "the alert mail");
            String body = sink.messages().stream().filter(m -> m.subject().contains("Bathroom since 14:00"))
                    .findFirst().orElseThrow().body().replaceAll("=\r?\n", ""); // quoted-printable soft breaks
            assertTrue(body, body.contains("Quiet for: 25 min"));
            assertTrue(body, body.contains("Why this is unusual: usually at most 10 min between 13:00 and 16:00 in "
                    + "Bathroom, from 1 day"));
        }
    }

    @Test
    public void aNightTripToTheBathroomThatDoesNotEndIsAlertedByTheBathroomsNightLimit() throws Exception {
        try (SyncPeer s = sync(); AmicaNode bed = node(1, 51, MOVEMENT); AmicaNode bath = node(1, 52, MOVEMENT);
                AmicaNode kitchen = node(1, 53, MOVEMENT)) {
            sync = s;
            Instant night1 = midnight().minus(Duration.ofHours(1)); // 23:00
            sync.tickDone(night1);
            placeIn(bed, "AmicaMovement", "Bedroom");
            placeIn(bath, "AmicaMovement", "Bathroom");
            placeIn(kitchen, "AmicaMovement", "Kitchen");
            setUp();

            // night 1: to bed at 23:00, bathroom 03:00 for 8 min, back to bed, up at 07:00
            motion(bed, "Bedroom");
            String asleep = parameter(device, "limitReason");
            assertTrue(asleep, asleep.contains("Bedroom asleep"));
            motionAt(night1.plus(Duration.ofHours(4)), bath, "Bathroom");
            motionAt(night1.plus(Duration.ofHours(4)).plus(Duration.ofMinutes(8)), bed, "Bedroom");
            motionAt(night1.plus(Duration.ofHours(8)), kitchen, "Kitchen");

            // night 2: to bed at 23:00; 03:00 bathroom, and no return
            Instant night2 = night1.plus(Duration.ofDays(1));
            motionAt(night2, bed, "Bedroom");
            String sleep = parameter(device, "limitReason");
            assertTrue(sleep, sleep.startsWith("usually at most 4 h between 22:00 and 01:00 asleep in Bedroom"));
            Instant up = night2.plus(Duration.ofHours(4));
            motionAt(up, bath, "Bathroom");
            await(TIMEOUT, () -> inactivity.state() == InactivityState.WATCHING, "WATCHING");
            String reason = parameter(device, "limitReason");
            assertTrue(reason, reason.startsWith("usually at most 8 min between 02:00 and 05:00 in Bathroom"));

            sync.tickDone(up.plus(Duration.ofMinutes(22)).minusSeconds(1));
            assertEquals(InactivityState.WATCHING, inactivity.state());
            sync.tickDone(up.plus(Duration.ofMinutes(22)));
            assertEquals("8 min x 1.5 + 10 min = 22 min after 03:00, not the sleep limit of 6 h 10 min",
                    InactivityState.ALERT, inactivity.state());
            assertEquals("Bathroom", inactivity.alert().orElseThrow().roomName());
        }
    }
}

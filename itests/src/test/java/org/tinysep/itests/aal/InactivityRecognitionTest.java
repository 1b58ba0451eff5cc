package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.api.device.Device;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * Inactivity Recognition end to end in virtual time: a real AmICA movement node over UDP placed in the bathroom,
 * Flat Occupancy, House Information, and the Mail Manager sending to a real SMTP server. A collapse in the
 * bathroom raises exactly one alert mail at last activity + 45 virtual minutes; the next movement clears it.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class InactivityRecognitionTest extends AalTestSupport {

    private static final DateTimeFormatter HH_MM = DateTimeFormatter.ofPattern("HH:mm").withZone(ZoneOffset.UTC);

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        return replacing(super.initialConfigurations(), "org.tinysep.inactivity", INACTIVITY_UTC);
    }

    @Test
    public void aCollapseInTheBathroomMailsOnceAndTheNextMovementClearsTheAlert() throws Exception {
        try (SmtpSink sink = new SmtpSink().start(); SyncPeer sync = sync(); AmicaNode bath = node(1, 40, MOVEMENT)) {
            mailTo(sink, "carer@care.test");
            Instant t = tomorrow();
            sync.tickDone(t);
            placeIn(bath, "AmicaMovement", "Bathroom");
            InactivityRecognitionProvider inactivity = awaitService(InactivityRecognitionProvider.class, null,
                    TIMEOUT);
            Device device = awaitService(Device.class, "(tinysep.device.uid=" + inactivity.deviceUid() + ")",
                    TIMEOUT);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);

            bath.motion(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "the flat OCCUPIED");
            await(TIMEOUT, () -> inactivity.state() == InactivityState.WATCHING, "WATCHING");
            await(TIMEOUT, () -> parameter(device, "lastActivity").contains("in Bathroom"), "the bathroom activity");

            sync.tickDone(t.plusSeconds(45 * 60 - 1));
            assertEquals(InactivityState.WATCHING, inactivity.state());
            sync.tickDone(t.plusSeconds(45 * 60));
            assertEquals("alert at last activity + 45 min", InactivityState.ALERT, inactivity.state());
            assertEquals("Bathroom", inactivity.alert().orElseThrow().roomName());
            assertTrue("mailed", sink.await(1, TIMEOUT));
            String subject = "TinySEP: no activity in Bathroom since " + HH_MM.format(t);
            assertEquals(subject, sink.messages().get(0).subject());
            assertTrue(sink.messages().get(0).body(), sink.messages().get(0).body().contains("Last activity: movement by"));

            Instant later = t.plusSeconds(50 * 60);
            sync.tickDone(later); // further ticks resend nothing (checked below by the order of the mails)
            bath.motion(true);
            await(TIMEOUT, () -> inactivity.state() == InactivityState.WATCHING, "the alert cleared by movement");
            assertTrue(inactivity.alert().isEmpty());

            sync.tickDone(later.plusSeconds(45 * 60));
            assertEquals(InactivityState.ALERT, inactivity.state());
            assertTrue("the second alert mailed", sink.await(2, TIMEOUT));
            assertEquals("TinySEP: no activity in Bathroom since " + HH_MM.format(later),
                    sink.messages().get(1).subject());
            assertEquals(2, sink.messages().size());
        }
    }
}

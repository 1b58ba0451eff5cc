package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.alert.NotificationStep;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.FlatOccupancyProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.Occupancy;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * Issue 25, item 1 end to end in virtual time: the only movement sensor of the flat, in the Bathroom, goes while an
 * inactivity alert is open (the installer removes its device, as a forged keep-alive that re-typed its node did).
 * Inactivity Recognition and Flat Occupancy stay, the alert stays OPEN and is still repeated, no all clear is sent,
 * and a {@code Monitoring reduced: } PROBLEM names the Bathroom.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WatchersStayTest extends AalTestSupport {

    private static final String FIRST = "first@care.test";
    private static final int LIMIT = 45 * 60; // the bathroom's limit

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts");
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.inactivity", INACTIVITY_UTC);
        configs.put("org.tinysep.alerts", Map.of("contacts", FIRST, "repeatMinutes", "10", "escalateMinutes", "0",
                "summaryTime", "", "timeZone", "UTC"));
        return configs;
    }

    @Test
    public void theWatchingServicesAndTheOpenAlertStayWhenTheOnlyMovementSensorGoes() throws Exception {
        try (SmtpSink sink = new SmtpSink().start(); SyncPeer sync = sync(); AmicaNode bath = node(1, 40, MOVEMENT)) {
            mailTo(sink, "carer@care.test");
            AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
            Instant t = tomorrow();
            sync.tickDone(t);
            Device movement = placeIn(bath, "AmicaMovement", "Bathroom");
            InactivityRecognitionProvider inactivity = awaitService(InactivityRecognitionProvider.class, null,
                    TIMEOUT);
            FlatOccupancyProvider flat = awaitService(FlatOccupancyProvider.class, null, TIMEOUT);
            bath.motion(true);
            await(TIMEOUT, () -> flat.occupancy() == Occupancy.OCCUPIED, "the flat OCCUPIED");
            await(TIMEOUT, () -> inactivity.state() == InactivityState.WATCHING, "WATCHING");
            sync.tickDone(t.plusSeconds(LIMIT));
            assertEquals(InactivityState.ALERT, inactivity.state());
            assertEquals("one open alert", 1, alerts.open().size());
            Alert a = alerts.open().get(0);
            assertTrue("first message mailed", sink.await(1, TIMEOUT));

            String said = shell("tinysep:remove " + movement.uid());
            await(TIMEOUT, () -> context.getServiceReference(org.tinysep.api.sensor.MovementProvider.class) == null,
                    "the movement sensor gone: " + said);
            await(TIMEOUT, () -> problems().stream().anyMatch(p -> p.startsWith("Monitoring reduced: ")),
                    "a Monitoring reduced problem");
            sync.tickDone(t.plusSeconds(LIMIT + 60));

            assertNotNull("Inactivity Recognition stays", context.getServiceReference(
                    InactivityRecognitionProvider.class));
            assertNotNull("Flat Occupancy stays", context.getServiceReference(FlatOccupancyProvider.class));
            InactivityRecognitionProvider still = awaitService(InactivityRecognitionProvider.class, null, TIMEOUT);
            assertEquals(InactivityState.ALERT, still.state());
            assertEquals("the alert is still open: " + alerts.alert(a.id()), AlertState.OPEN,
                    alerts.alert(a.id()).orElseThrow().state());
            List<String> reduced = problems().stream().filter(p -> p.startsWith("Monitoring reduced: ")).toList();
            assertTrue(reduced.toString(), reduced.stream().anyMatch(p -> p.startsWith("Monitoring reduced: "
                    + "Inactivity recognition can no longer see the Bathroom: its sensor")));
            assertTrue(reduced.toString(), reduced.stream().anyMatch(p -> p.startsWith("Monitoring reduced: "
                    + "Flat occupancy can no longer see the Bathroom")));
            Device watcher = awaitService(Device.class, "(" + DeviceProperties.DEVICE_UID + "="
                    + still.deviceUid() + ")", TIMEOUT);
            assertTrue(parameter(watcher, "roomsNotSeen"), parameter(watcher, "roomsNotSeen").startsWith(
                    "Bathroom (its sensor "));

            sync.tickDone(t.plusSeconds(LIMIT + 10 * 60)); // nobody acknowledged: it is still repeated
            Alert later = alerts.alert(a.id()).orElseThrow();
            assertEquals(AlertState.OPEN, later.state());
            assertEquals(later.notifications().toString(), NotificationStep.REPEAT,
                    later.notifications().get(later.notifications().size() - 1).step());
            assertTrue("the repeat mailed", sink.await(2, TIMEOUT));
            assertFalse("no all clear: " + sink.messages(), sink.messages().stream()
                    .anyMatch(m -> AlertEscalationTest.unfolded(m.data()).startsWith("All clear")));
            assertFalse(events(), events().contains("alert " + a.id() + " cleared"));
        }
    }

    private List<String> problems() {
        EventLog log = awaitService(EventLog.class, null, TIMEOUT);
        return log.recent(5000).stream().filter(e -> e.kind() == EventKind.PROBLEM).map(EventEntry::message)
                .toList();
    }

    private String events() {
        EventLog log = awaitService(EventLog.class, null, TIMEOUT);
        return log.recent(5000).stream().map(e -> e.origin() + ": " + e.message()).collect(Collectors.joining("\n"));
    }
}

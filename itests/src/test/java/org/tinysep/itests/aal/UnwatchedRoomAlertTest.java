package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.health.SensorHealthProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * Issue 12.2, a dead sensor is not inactivity, end to end in virtual time: the person was last seen in the
 * Bathroom, then the Bathroom's only sensor falls silent (battery) while the Kitchen's keeps reporting. The
 * inactivity alert that follows (a real SMTP server) says the Bathroom could not be watched, and since when.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class UnwatchedRoomAlertTest extends AalTestSupport {

    private static final DateTimeFormatter HH_MM = DateTimeFormatter.ofPattern("HH:mm").withZone(ZoneOffset.UTC);

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.sensorhealth");
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.inactivity", Map.of("timeZone", "UTC", "detector", "THESIS"));
        configs.put("org.tinysep.sensorhealth", Map.of("timeZone", "UTC"));
        return configs;
    }

    @Test
    public void anAlertWhileTheBathroomSensorIsOfflineSaysTheBathroomCouldNotBeWatched() throws Exception {
        try (SmtpSink sink = new SmtpSink().start(); SyncPeer sync = sync(); AmicaNode bath = node(1, 61, MOVEMENT);
                AmicaNode kitchen = node(1, 62, MOVEMENT)) {
            mailTo(sink, "carer@care.test");
            Instant t = tomorrow().plus(Duration.ofHours(10));
            sync.tickDone(t);
            placeIn(bath, "AmicaMovement", "Bathroom");
            placeIn(kitchen, "AmicaMovement", "Kitchen");
            InactivityRecognitionProvider inactivity = awaitService(InactivityRecognitionProvider.class, null,
                    TIMEOUT);
            SensorHealthProvider health = awaitService(SensorHealthProvider.class, null, TIMEOUT);
            Device bathBus = awaitService(Device.class, "(&(" + DeviceProperties.NODE_ADDRESS + "=1.61)("
                    + DeviceProperties.DEVICE_TYPE + "=" + BUS + "))", TIMEOUT);

            bath.motion(true);
            bath.motion(false);
            sync.tickDone(t = t.plusSeconds(1)); // the frames are handled before this tick's DONE
            await(TIMEOUT, () -> inactivity.state() == InactivityState.WATCHING, "WATCHING after the Bathroom");
            Instant lastHeard = t;

            // the Bathroom node is silent from now on; the Kitchen node keeps reporting; 45 min: Bathroom's limit
            Instant alertDue = lastHeard.plus(Duration.ofMinutes(46));
            while (t.isBefore(alertDue) && inactivity.state() != InactivityState.ALERT) {
                kitchen.keepAlive();
                sync.tickDone(t = t.plusSeconds(30));
            }
            assertEquals(DeviceStatus.State.OFFLINE, bathBus.status().state());
            assertTrue(health.unmonitoredRooms().toString(), health.unmonitoredRooms().stream()
                    .anyMatch(r -> r.roomName().equals("Bathroom")));
            assertEquals(InactivityState.ALERT, inactivity.state());
            assertEquals("Bathroom", inactivity.alert().orElseThrow().roomName());
            await(TIMEOUT, () -> sink.messages().stream().anyMatch(m -> m.subject().contains("no activity in")),
                    "the alert mail");
            String body = sink.messages().stream().filter(m -> m.subject().contains("no activity in")).findFirst()
                    .orElseThrow().body().replaceAll("=\r?\n", ""); // quoted-printable soft breaks
            String since = HH_MM.format(health.unmonitoredRooms().stream()
                    .filter(r -> r.roomName().equals("Bathroom")).findFirst().orElseThrow().since());
            assertTrue(body, body.contains("Could not be watched: Bathroom (no sensor heard since " + since + ")"));
            Device flat = awaitService(Device.class, "(" + DeviceProperties.DRIVER_NAME + "=FlatOccupancy)", TIMEOUT);
            String unmonitored = flat.parameters().stream().filter(p -> p.key().equals("unmonitoredRooms"))
                    .map(p -> p.value()).findFirst().orElse("");
            assertTrue("Flat Occupancy says which room cannot be heard: " + unmonitored,
                    unmonitored.startsWith("Bathroom (no sensor heard since "));
            assertTrue(body, !body.contains("Could not be watched: Bathroom (no sensor heard since " + since
                    + "), Kitchen"));
        }
    }
}

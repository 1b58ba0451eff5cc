package org.tinysep.itests.health;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.api.health.SensorHealthProvider;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.itests.TestSyncKey;
import org.tinysep.itests.TinySepTestSupport;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * Sensor health end to end in virtual time (issue 12.1/12.2): a movement node placed in the Bathroom falls silent
 * and goes OFFLINE after the configured report intervals, with a PROBLEM entry; the caregiver gets a notice mail
 * (a real SMTP server) "sensor offline in Bathroom since HH:mm"; the next frame brings it back ONLINE (and a "back
 * online" notice); a low keep-alive battery is reported once.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class SensorHealthTest extends TinySepTestSupport {

    private static final DateTimeFormatter HH_MM = DateTimeFormatter.ofPattern("HH:mm").withZone(ZoneOffset.UTC);

    @Override
    protected List<String> applications() {
        List<String> apps = new ArrayList<>(FIRST_SLICE);
        apps.addAll(List.of("org.tinysep.houseinformation", "org.tinysep.timecontroller", "org.tinysep.mailmanager",
                "org.tinysep.sensorhealth"));
        return apps;
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put(UDP_PID, Map.of("port", "0", "bindAddress", "127.0.0.1", "silentAfterIntervals", "5"));
        configs.put("org.tinysep.timecontroller", TestSyncKey.timeConfig("EXTERNAL"));
        configs.put("org.tinysep.sensorhealth", Map.of("noticeAfterMinutes", "1", "timeZone", "UTC"));
        try {
            Path dir = Files.createTempDirectory("tinysep-health-");
            configs.put("org.tinysep.houseinformation", Map.of("file", dir.resolve("house.xml").toString()));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return configs;
    }

    private static String parameter(Device device, String key) {
        return device.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElse(null);
    }

    private List<String> problems(String origin) {
        EventLog events = awaitService(EventLog.class, null, TIMEOUT);
        return events.recent(10_000).stream().filter(e -> e.kind() == EventKind.PROBLEM && e.origin().equals(origin))
                .map(e -> e.message()).toList();
    }

    @Test
    public void aSilentSensorGoesOfflineTheCaregiverIsToldAndItComesBack() throws Exception {
        MailManagerProvider mail = awaitService(MailManagerProvider.class, null, TIMEOUT);
        TimeControllerProvider clock = awaitService(TimeControllerProvider.class, null, TIMEOUT);
        SensorHealthProvider health = awaitService(SensorHealthProvider.class, null, TIMEOUT);
        shell("tinysep:room-add Bathroom Bathroom");
        try (SmtpSink sink = new SmtpSink().start(); SyncPeer sync = new SyncPeer(syncPort(), 10_000);
                AmicaNode node = new AmicaNode(1, 1, udpPortOf("BusRadioAmicaUdp"), AmicaNodeType.MOVEMENT)) {
            configure("org.tinysep.mailmanager", Map.of("host", "127.0.0.1", "port", Integer.toString(sink.port()),
                    "security", "NONE", "from", "tinysep@home.test", "recipients", "carer@care.test",
                    "connectTimeoutSeconds", "2", "retryInitialSeconds", "1", "retryMaxSeconds", "2"));
            await(TIMEOUT, () -> mail.status() == MailStatus.IDLE, "the Mail Manager configured");

            Instant t = clock.now().truncatedTo(ChronoUnit.SECONDS).plusSeconds(1);
            sync.tickDone(t);
            node.keepAlive();
            sync.tickDone(t = t.plusSeconds(1)); // the keep-alive is handled before this tick's DONE
            NodeHealthSource bus = awaitService(NodeHealthSource.class, "(" + DeviceProperties.NODE_ADDRESS
                    + "=1.1)", TIMEOUT);
            Device busDevice = awaitService(Device.class, "(&(" + DeviceProperties.NODE_ADDRESS + "=1.1)("
                    + DeviceProperties.DEVICE_TYPE + "=BusRadioAmicaUdp))", TIMEOUT);
            Device movement = awaitService(Device.class, "(&(" + DeviceProperties.NODE_ADDRESS + "=1.1)("
                    + DeviceProperties.DEVICE_TYPE + "=AmicaMovement))", TIMEOUT);
            shell("tinysep:set " + movement.uid() + " room Bathroom");
            Instant lastHeard = bus.health().lastHeard();
            assertEquals(DeviceStatus.State.ONLINE, busDevice.status().state());

            // a movement node promises a report every 2 s; 5 missed intervals = 10 s of silence
            for (int s = 1; s < 10; s++) {
                sync.tickDone(lastHeard.plusSeconds(s));
            }
            assertEquals("still within its intervals", DeviceStatus.State.ONLINE, busDevice.status().state());
            sync.tickDone(lastHeard.plusSeconds(10));
            assertEquals(DeviceStatus.State.OFFLINE, busDevice.status().state());
            assertTrue(busDevice.status().detail(), busDevice.status().detail().startsWith("silent since "));
            List<String> problems = problems(busDevice.uid());
            assertEquals(problems.toString(), 1, problems.size());
            assertTrue(problems.get(0), problems.get(0).startsWith("AmICA node 1.1 (AmICA node 1.1) has not been "
                    + "heard since ") && problems.get(0).contains("It is OFFLINE until it is heard again."));
            String listing = shell("tinysep:devices 1.1");
            assertTrue(listing, listing.contains("[OFFLINE") && listing.contains("linkQuality="));

            sync.tickDone(lastHeard.plusSeconds(11));
            await(TIMEOUT, () -> health.unmonitoredRooms().stream().anyMatch(r -> r.roomName().equals("Bathroom")),
                    "the Bathroom unmonitored");
            assertEquals("no notice before noticeAfterMinutes", 0, sink.messages().size());
            sync.tickDone(lastHeard.plusSeconds(71));
            sync.tickDone(lastHeard.plusSeconds(72));
            assertTrue("the offline notice mailed", sink.await(1, TIMEOUT));
            assertEquals("TinySEP notice: sensor offline in Bathroom since " + HH_MM.format(lastHeard),
                    sink.messages().get(0).subject());
            assertTrue(sink.messages().get(0).body(), sink.messages().get(0).body().startsWith(
                    "This is a notice about the sensors, not an alarm"));

            node.motion(false);
            sync.tickDone(lastHeard.plusSeconds(73)); // the frame is handled before this DONE
            assertEquals("ONLINE again with the next frame", DeviceStatus.State.ONLINE, busDevice.status().state());
            sync.tickDone(lastHeard.plusSeconds(74));
            assertTrue("the back-online notice mailed", sink.await(2, TIMEOUT));
            assertEquals("TinySEP notice: sensor back online in Bathroom", sink.messages().get(1).subject());
            assertTrue(health.unmonitoredRooms().isEmpty());

            // low battery: two AA cells near empty, reported once before the node dies
            node.send(new KeepAlive(300, 2150, 0x0A11, AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 4242));
            sync.tickDone(lastHeard.plusSeconds(75));
            assertTrue(bus.health().batteryLow());
            List<String> battery = problems(busDevice.uid()).stream().filter(p -> p.contains("low battery")).toList();
            assertEquals(List.of("AmICA node 1.1 (AmICA node 1.1) reports a low battery: 2150 mV (low below 2200 mV). "
                    + "Replace or recharge it soon, before the node stops reporting."), battery);
            assertTrue(parameter(busDevice, "battery"), parameter(busDevice, "battery").startsWith("2150 mV LOW"));
            sync.tickDone(lastHeard.plusSeconds(76));
            assertTrue("the low-battery notice mailed", sink.await(3, TIMEOUT));
            assertEquals("TinySEP notice: low battery in Bathroom", sink.messages().get(2).subject());
            node.send(new KeepAlive(302, 2140, 0x0A11, AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 4242));
            sync.tickDone(lastHeard.plusSeconds(77));
            sync.tickDone(lastHeard.plusSeconds(78));
            assertFalse("reported once", problems(busDevice.uid()).stream().filter(p -> p.contains("low battery"))
                    .count() > 1);
        }
    }
}

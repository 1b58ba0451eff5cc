package org.tinysep.itests.time;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.DatagramSocket;
import java.net.InetAddress;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.ServiceReference;
import org.osgi.service.cm.ConfigurationAdmin;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.TimeControllerListener;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.SyncPeer;

/**
 * The clock switches between REAL and EXTERNAL at runtime, by ConfigAdmin, device parameter and shell command,
 * while the device, its service and its listeners' connections stay (no restart).
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class TimeModeSwitchTest extends TimeTestSupport {

    @Override
    String initialMode() {
        return "REAL";
    }

    private final List<String> heard = new CopyOnWriteArrayList<>();
    private final List<Instant> ticks = new CopyOnWriteArrayList<>();

    private final TimeControllerListener listener = new TimeControllerListener() {
        @Override
        public void timeAdvanced(TimeControllerProvider source, Instant now) {
            ticks.add(now);
        }

        @Override
        public void modeChanged(TimeControllerProvider source, ClockMode mode, Instant at) {
            heard.add(mode.name());
        }
    };

    private long serviceId() {
        ServiceReference<TimeControllerProvider> ref = context.getServiceReference(TimeControllerProvider.class);
        return (Long) ref.getProperty("service.id");
    }

    @Test
    public void switchesBackAndForthWithoutRestartKeepingDeviceAndConnections() throws Exception {
        TimeControllerProvider clock = clock();
        long id = serviceId();
        String uid = clock.deviceUid();
        Connection connection = clock.connect(listener);
        int port = syncPort();
        assertEquals(ClockMode.REAL, clock.mode());
        await(TIMEOUT, () -> ticks.size() >= 2, "two real-time ticks");
        assertTrue(Duration.between(clock.now(), Instant.now()).abs().toSeconds() < 2);

        try (SyncPeer sync = new SyncPeer(port)) {
            assertTrue(sync.tick(Instant.now().plusSeconds(5)).startsWith("ERROR 1 not-external "));

            configure(TIME_PID, config("EXTERNAL")); // 1. ConfigAdmin
            await(TIMEOUT, () -> clock.mode() == ClockMode.EXTERNAL, "EXTERNAL after the configuration update");
            Instant held = clock.now();
            int ticksAtSwitch = ticks.size();
            assertTrue(sync.ask("HELLO").startsWith("WELCOME " + held + " EXTERNAL "));
            Instant future = held.plus(Duration.ofDays(3));
            sync.tickDone(future);
            assertEquals(future, clock.now());
            assertEquals(future, ticks.get(ticks.size() - 1));
            assertEquals("no real-time tick in EXTERNAL mode", ticksAtSwitch + 1, ticks.size());

            String shown = shell("tinysep:time real"); // 2. shell command
            assertTrue(shown, shown.contains("mode       REAL")
                    && shown.contains("sync port  " + port + " (listening on 127.0.0.1:" + port + ")"));
            assertTrue(Duration.between(clock.now(), Instant.now()).abs().toSeconds() < 2);
            assertEquals("the shell's choice is stored", "REAL", admin().getConfiguration(TIME_PID, "?")
                    .getProperties().get("mode"));

            shell("tinysep:set " + uid + " mode external"); // 3. device parameter
            assertEquals(ClockMode.EXTERNAL, clock.mode());
            await(TIMEOUT, () -> "EXTERNAL".equals(storedMode()), "the parameter's choice to be stored");
            assertTrue(sync.tick(clock.now().plusSeconds(1)).startsWith("DONE "));
            shell("tinysep:time real");
        }
        assertEquals(List.of("EXTERNAL", "REAL", "EXTERNAL", "REAL"), heard);
        assertTrue(connection.isOpen());
        assertEquals("same service, no restart", id, serviceId());
        assertEquals(uid, clock.deviceUid());
        int before = ticks.size();
        await(TIMEOUT, () -> ticks.size() >= before + 2, "real-time ticks again");

        EventLog log = awaitService(EventLog.class, null, TIMEOUT);
        long switches = log.recent(1000).stream().filter(e -> e.message().startsWith("clock switched to")).count();
        assertEquals(4, switches);
        String devices = shell("tinysep:devices");
        assertTrue(devices, devices.contains("mode") && devices.contains("syncLink"));
    }

    @Test
    public void aBadModeIsRefusedWithAClearMessageAndChangesNothing() throws Exception {
        TimeControllerProvider clock = clock();
        try {
            shell("tinysep:time sideways");
            throw new IllegalStateException("accepted a bad mode");
        } catch (AssertionError expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("unknown clock mode 'sideways'"));
        }
        configure(TIME_PID, config("SIDEWAYS"));
        EventLog log = awaitService(EventLog.class, null, TIMEOUT);
        await(TIMEOUT, () -> log.recent(100).stream().anyMatch(e -> e.message().contains("'SIDEWAYS'")),
                "the bad configuration to be reported");
        assertEquals(ClockMode.REAL, clock.mode());
        Device device = awaitService(Device.class, "(" + DeviceProperties.DEVICE_TYPE + "=TimeController)", TIMEOUT);
        assertEquals(clock.deviceUid(), device.uid());
    }

    @Test
    public void aNewPortReopensTheLinkAndIsPublished() throws Exception {
        int old = syncPort();
        int port;
        try (DatagramSocket probe = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            port = probe.getLocalPort();
        }
        configure(TIME_PID, Map.of("mode", "EXTERNAL", "syncPort", Integer.toString(port),
                "syncBindAddress", "127.0.0.1"));
        await(TIMEOUT, () -> syncPort() == port, "the Driver service to publish port " + port + " (was " + old + ")");
        TimeControllerProvider clock = clock();
        try (SyncPeer sync = new SyncPeer(port)) {
            assertTrue(sync.ask("HELLO").startsWith("WELCOME " + clock.now() + " EXTERNAL "));
        }
    }

    private ConfigurationAdmin admin() {
        return awaitService(ConfigurationAdmin.class, null, TIMEOUT);
    }

    private String storedMode() {
        try {
            Object mode = admin().getConfiguration(TIME_PID, "?").getProperties().get("mode");
            return mode == null ? null : mode.toString();
        } catch (Exception e) {
            return e.toString();
        }
    }
}

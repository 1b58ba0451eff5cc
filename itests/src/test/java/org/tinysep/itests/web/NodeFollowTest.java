package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.HashMap;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.itests.TestSyncKey;

/**
 * Devices follow their bus node (issue 32, item 3), in a real Felix in virtual time: a node with a door and a light
 * falls silent; its bus device goes OFFLINE, and so do the door and the light, in {@code tinysep:devices} and in
 * {@code GET /api/devices}, each with the reason in words and no STATUS entry of its own; the node's next frames
 * bring them back ONLINE. The door being the inactivity watch's only sensor, {@code GET /api/caregiver} says the
 * watch is blind meanwhile.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class NodeFollowTest extends WebTestSupport {

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new HashMap<>(super.initialConfigurations());
        configs.put(UDP_PID, Map.of("port", "0", "bindAddress", "127.0.0.1", "silentAfterIntervals", "5"));
        configs.put("org.tinysep.timecontroller", TestSyncKey.timeConfig("EXTERNAL"));
        return configs;
    }

    private Device device(String type) {
        return awaitService(Device.class, "(&(" + DeviceProperties.NODE_ADDRESS + "=1.4)(" + DeviceProperties.DEVICE_TYPE
                + "=" + type + "))", TIMEOUT);
    }

    /** @return the state and detail the API gives the device: {@code STATE|detail} */
    private static String apiStatus(String devicesJson, String uid) {
        Matcher m = Pattern.compile("\\{\"uid\":\"" + Pattern.quote(uid) + "\",[^{]*\"status\":\\{\"state\":\"([A-Z]+)\","
                + "\"detail\":\"([^\"]*)\"").matcher(devicesJson);
        assertTrue(uid + " in " + devicesJson, m.find());
        return m.group(1) + "|" + m.group(2);
    }

    private long statusEntries(String uid) {
        return awaitService(EventLog.class, null, TIMEOUT).recent(10_000).stream()
                .filter(e -> e.kind() == EventKind.STATUS && e.origin().equals(uid)).count();
    }

    @Test
    public void theDevicesOfASilentNodeAreOfflineWithItAndComeBackWithIt() throws Exception {
        setPasswords();
        Login login = login("installer", INSTALLER_PASSWORD);
        TimeControllerProvider clock = awaitService(TimeControllerProvider.class, null, TIMEOUT);
        try (SyncPeer sync = new SyncPeer(syncPort(), 10_000);
                AmicaNode node = node(1, 4, AmicaNodeType.DOOR, AmicaNodeType.SIMPLE_LIGHT)) {
            Instant t = clock.now().truncatedTo(ChronoUnit.SECONDS).plusSeconds(1);
            sync.tickDone(t);
            node.keepAlive();
            node.door(false);
            node.send(new LightControl(0));
            sync.tickDone(t = t.plusSeconds(1)); // the frames are handled before this tick's DONE
            Device bus = device(BUS);
            Device door = device("AmicaDoor");
            Device light = device("AmicaSimpleLight");
            await(TIMEOUT, () -> light.status().state() == DeviceStatus.State.ONLINE
                    && door.status().state() == DeviceStatus.State.ONLINE, "the door and the light ONLINE");
            long doorEntries = statusEntries(door.uid());
            long lightEntries = statusEntries(light.uid());

            // a door promises a report every second: 5 missed intervals = 5 s of silence
            for (int s = 1; s <= 6; s++) {
                sync.tickDone(t.plusSeconds(s));
            }
            assertEquals(DeviceStatus.State.OFFLINE, bus.status().state());
            for (Device d : new Device[] {door, light}) {
                DeviceStatus s = d.status();
                assertEquals(d.type(), DeviceStatus.State.OFFLINE, s.state());
                assertTrue(s.detail(), s.detail().startsWith("its radio node 1.4 has been silent since ")
                        && s.detail().contains(bus.uid()));
            }
            String listing = shell("tinysep:devices 1.4");
            assertTrue(listing, listing.contains(light.uid()) && listing.contains(door.uid()));
            assertFalse("nothing of node 1.4 ONLINE: " + listing, listing.contains("[ONLINE"));
            assertTrue(listing, listing.contains("[OFFLINE (its radio node 1.4 has been silent since "));
            String api = call("GET", "/api/devices", null, login, false).body();
            assertTrue(apiStatus(api, light.uid()), apiStatus(api, light.uid())
                    .startsWith("OFFLINE|its radio node 1.4 has been silent since "));
            assertTrue(apiStatus(api, door.uid()), apiStatus(api, door.uid()).startsWith("OFFLINE|"));
            assertEquals("the door writes no STATUS entry of its own", doorEntries, statusEntries(door.uid()));
            // the door is the inactivity watch's only sensor: the caregiver sees the watch blind, not "watching"
            String caregiver = call("GET", "/api/caregiver", null, login, false).body();
            assertTrue(caregiver, caregiver.contains("\"blind\":true,\"sensors\":1,\"sensorsOffline\":1,"
                    + "\"sight\":\"Blind: all 1 of its sensors are offline ("));
            assertEquals("the light writes no STATUS entry of its own", lightEntries, statusEntries(light.uid()));

            node.door(true);
            node.send(new LightControl(0));
            sync.tickDone(t.plusSeconds(7));
            assertEquals(DeviceStatus.State.ONLINE, bus.status().state());
            assertEquals(DeviceStatus.State.ONLINE, door.status().state());
            assertEquals(DeviceStatus.State.ONLINE, light.status().state());
            api = call("GET", "/api/devices", null, login, false).body();
            assertEquals("ONLINE|", apiStatus(api, light.uid()));
            assertEquals("ONLINE|", apiStatus(api, door.uid()));
            caregiver = call("GET", "/api/caregiver", null, login, false).body();
            assertTrue(caregiver, caregiver.contains("\"blind\":false,\"sensors\":1,\"sensorsOffline\":0,"));
        }
    }
}

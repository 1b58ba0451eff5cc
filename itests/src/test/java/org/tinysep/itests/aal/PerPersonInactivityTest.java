package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.Option;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.PersonWatch;
import org.tinysep.itests.AmicaNode;
import org.tinysep.itests.SyncPeer;
import org.tinysep.sunspot.protocol.AccelerationSample;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/**
 * Activity per person (issue 26, item 4) in a real Felix, in lock-step virtual time: person nodes send real Sun SPOT
 * type-6 frames over UDP on 127.0.0.1, a real AmICA movement node in the kitchen; Sun SPOT Person, Flat Occupancy,
 * Inactivity Recognition and the alert service do the rest. (a) Anna's pendant lies still while Bert's moves and
 * the kitchen sensor keeps seeing him: Anna is alerted by name after the kitchen's limit, Bert is not. (b) One
 * person whose pendant lies still while the kitchen sensor keeps seeing someone: a "not worn" notice, no alert.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class PerPersonInactivityTest extends AalTestSupport {

    private static final DateTimeFormatter HH_MM = DateTimeFormatter.ofPattern("HH:mm").withZone(ZoneOffset.UTC);
    private static final String PERSON_DEVICE = "(" + DeviceProperties.DRIVER_NAME + "=SunSpotPerson)";
    private static final MovementSummaryReport STILL =
            new MovementSummaryReport(2000, new AccelerationSample(10, -990, 60), 4, 1000);
    private static final MovementSummaryReport MOVING =
            new MovementSummaryReport(2000, new AccelerationSample(60, -950, 120), 210, 1700);

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.addAll(sunSpotBundles(5));
        o.add(reactorBundle("org.tinysep.sunspot.person", 5));
        return o;
    }

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts");
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = replacing(super.initialConfigurations(), "org.tinysep.inactivity",
                Map.of("timeZone", "UTC", "detector", "THESIS", "typeLimits", "Kitchen=30",
                        "personNotWornMinutes", "60"));
        configs.put("org.tinysep.alerts", Map.of("contacts", "carer@care.test", "summaryTime", "", "timeZone", "UTC"));
        return configs;
    }

    /** A person node: real frames, one per datagram, from its own socket. */
    private final class PersonNode implements AutoCloseable {
        final SunSpotAddress address;
        final DatagramSocket socket;
        final InetSocketAddress radio;
        Device device;

        PersonNode(String address) throws IOException {
            this.address = SunSpotAddress.parse(address);
            this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
            this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), udpPortOf("BusRadioSunSpot"));
        }

        void send(MovementSummaryReport p) throws IOException {
            byte[] frame = SunSpotCodec.encode(SunSpotFrame.of(address, SunSpotPayloads.encode(p)));
            socket.send(new DatagramPacket(frame, frame.length, radio));
        }

        /** Switches the node on and names its wearer. */
        PersonNode wornBy(String person) throws IOException {
            send(STILL);
            device = awaitService(Device.class, "(&(tinysep.node.address=" + address + ")" + PERSON_DEVICE + ")",
                    TIMEOUT);
            device.setParameter("person", person);
            return this;
        }

        String uid() {
            return device.uid();
        }

        @Override
        public void close() {
            socket.close();
        }
    }

    private InactivityRecognitionProvider inactivity() {
        return awaitService(InactivityRecognitionProvider.class, null, TIMEOUT);
    }

    private Optional<PersonWatch> watch(String person) {
        return inactivity().persons().stream().filter(p -> p.person().equals(person)).findFirst();
    }

    /**
     * Sends a summary and waits until Inactivity Recognition has taken it: the node's wearer watched; a movement
     * also taken as the flat's activity. The wearer's watch takes a movement before the flat does (on the Sun SPOT
     * radio's thread, with a save between them): a room sensor's frame sent as soon as the watch has it could be
     * taken by the flat first and then be followed by the pendant's, the flat's last activity then being the
     * pendant's, as a CI run showed.
     */
    private void summary(PersonNode node, String person, MovementSummaryReport s, Instant now) throws IOException {
        node.send(s);
        if (s == MOVING) {
            await(TIMEOUT, () -> watch(person).map(w -> w.lastMovement().equals(now)).orElse(false),
                    person + "'s movement at " + now + " taken");
            Device flat = awaitService(Device.class, "(tinysep.device.uid=" + inactivity().deviceUid() + ")",
                    TIMEOUT);
            await(TIMEOUT, () -> parameter(flat, "lastActivity").startsWith(person + "'s pendant moved")
                    && parameter(flat, "lastActivity").endsWith(" at " + now),
                    () -> person + "'s movement at " + now + " taken as the flat's activity; the flat's last activity: "
                            + parameter(flat, "lastActivity"));
        } else {
            await(TIMEOUT, () -> watch(person).isPresent(), person + " watched");
        }
    }

    /** Motion in the kitchen, and waits until Inactivity Recognition has taken it. */
    private void motion(AmicaNode kitchen, Device inactivityDevice, Instant now) throws IOException {
        kitchen.motion(true);
        await(TIMEOUT, () -> parameter(inactivityDevice, "lastActivity").startsWith("movement by ")
                && parameter(inactivityDevice, "lastActivity").endsWith("in Kitchen at " + now),
                () -> "the kitchen's motion at " + now + "; Inactivity Recognition's parameters: "
                        + inactivityDevice.parameters());
    }

    private List<String> events(String origin) {
        return awaitService(EventLog.class, null, TIMEOUT).recent(100_000).stream()
                .filter(e -> e.origin().equals(origin)).map(EventEntry::message).toList();
    }

    @Test
    public void annaStillWhileBertMovesAndTheKitchenIsBusyIsAlertedByNameBertIsNot() throws Exception {
        try (SyncPeer sync = sync(); AmicaNode kitchen = node(1, 41, MOVEMENT);
                PersonNode anna = new PersonNode("0014.4F01.0000.A001");
                PersonNode bert = new PersonNode("0014.4F01.0000.B002")) {
            AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
            Instant t = tomorrow();
            sync.tickDone(t);
            placeIn(kitchen, "AmicaMovement", "Kitchen");
            anna.wornBy("Anna");
            bert.wornBy("Bert");
            Device inactivityDevice = awaitService(Device.class, "(tinysep.device.uid=" + inactivity().deviceUid()
                    + ")", TIMEOUT);
            summary(anna, "Anna", STILL, t);
            summary(bert, "Bert", STILL, t);
            summary(anna, "Anna", MOVING, t); // Anna alone moves: the kitchen's motion is hers
            motion(kitchen, inactivityDevice, t);
            await(TIMEOUT, () -> watch("Anna").get().state() == InactivityState.WATCHING, "Anna watched");
            assertEquals(Optional.of("Kitchen"), watch("Anna").get().lastRoom());

            for (int k = 1; k <= 5; k++) { // Bert moves about the kitchen; Anna's pendant lies still
                Instant now = t.plusSeconds(k * 300);
                sync.tickDone(now);
                summary(bert, "Bert", MOVING, now);
                summary(anna, "Anna", STILL, now);
                motion(kitchen, inactivityDevice, now);
            }
            sync.tickDone(t.plusSeconds(30 * 60 - 1));
            assertEquals(InactivityState.WATCHING, watch("Anna").get().state());
            assertTrue(alerts.open().isEmpty());
            sync.tickDone(t.plusSeconds(30 * 60));
            await(TIMEOUT, () -> alerts.open().size() == 1, "Anna's alert");
            Alert a = alerts.open().get(0);
            assertEquals(AlertKind.INACTIVITY, a.kind());
            assertEquals("inactivity:" + anna.uid(), a.source());
            assertEquals("TinySEP: Anna has not been active since " + HH_MM.format(t) + " (last seen in Kitchen)",
                    a.subject());
            assertTrue(a.text(), a.text().contains("Pendant: has been still since " + HH_MM.format(t)
                    + " (30 min)"));
            assertTrue(a.text(), a.text().contains("Meanwhile the room sensors saw activity 5 times, each while the "
                    + "node of Bert was moving, so it was not counted as Anna's."));
            assertEquals(InactivityState.ALERT, watch("Anna").get().state());
            assertEquals(InactivityState.WATCHING, watch("Bert").get().state());
            assertEquals("the flat is busy", InactivityState.WATCHING, inactivity().state());
            assertTrue(watch("Anna").get().worn());

            sync.tickDone(t.plusSeconds(31 * 60));
            summary(anna, "Anna", MOVING, t.plusSeconds(31 * 60));
            await(TIMEOUT, () -> alerts.open().isEmpty(), "Anna's alert cleared by her pendant's movement");
            assertEquals("only Anna was alerted", 1, alerts.recent(10).size());
        }
    }

    @Test
    public void aPendantLyingStillWhileTheKitchenSeesSomeoneIsNotWornNotAnAlarm() throws Exception {
        try (SyncPeer sync = sync(); AmicaNode kitchen = node(1, 42, MOVEMENT);
                PersonNode anna = new PersonNode("0014.4F01.0000.A003")) {
            AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
            Instant t = tomorrow();
            sync.tickDone(t);
            placeIn(kitchen, "AmicaMovement", "Kitchen");
            anna.wornBy("Anna");
            Device inactivityDevice = awaitService(Device.class, "(tinysep.device.uid=" + inactivity().deviceUid()
                    + ")", TIMEOUT);
            summary(anna, "Anna", STILL, t);
            summary(anna, "Anna", MOVING, t);
            motion(kitchen, inactivityDevice, t);
            String notice = "Anna's pendant seems not to be worn: it has not moved since " + HH_MM.format(t)
                    + " while the sensors saw someone in the Kitchen; until it moves again, Anna is watched by the "
                    + "room sensors";
            for (int k = 1; k <= 7; k++) { // the pendant lies on a table; Anna cooks
                Instant now = t.plusSeconds(k * 600);
                sync.tickDone(now);
                summary(anna, "Anna", STILL, now);
                motion(kitchen, inactivityDevice, now);
                assertEquals("the notice comes at 60 min, not before (+" + k * 10 + " min)", k >= 6,
                        events(inactivity().deviceUid()).contains(notice));
            }
            assertEquals(false, watch("Anna").get().worn());
            assertEquals(InactivityState.WATCHING, watch("Anna").get().state());
            assertEquals("said once", 1, events(inactivity().deviceUid()).stream().filter(notice::equals).count());
            assertTrue("no alert: " + alerts.recent(10), alerts.recent(10).isEmpty());

            Instant worn = t.plusSeconds(75 * 60);
            sync.tickDone(worn);
            summary(anna, "Anna", MOVING, worn);
            await(TIMEOUT, () -> events(inactivity().deviceUid()).contains("Anna's pendant is worn again: it moved at "
                    + HH_MM.format(worn) + "; its movement counts as Anna's activity again"), "worn again");
            assertTrue(watch("Anna").get().worn());
            assertTrue(alerts.recent(10).isEmpty());
        }
    }
}

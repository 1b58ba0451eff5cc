package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.Option;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.itests.SyncPeer;
import org.tinysep.sunspot.protocol.AccelerationSample;
import org.tinysep.sunspot.protocol.ButtonReport;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * The help button (issue 26, item 2) in a real Felix, in lock-step virtual time: a Sun SPOT person node sends real
 * frames over UDP on 127.0.0.1 to the Sun SPOT bus radio; Sun SPOT Person, the help button, the alert service, the
 * Mail Manager and a real SMTP server do the rest. Each frame is stamped with the platform time of its arrival.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class HelpButtonTest extends AalTestSupport {

    private static final String CARER = "carer@care.test";
    private static final String FIRST = "first@care.test";
    private static final String ANNA = "0014.4F01.0000.A001";
    /** The Sun SPOT Person device (the node's bus device has the same address and node type). */
    private static final String PERSON_DEVICE = "(" + DeviceProperties.DRIVER_NAME + "=SunSpotPerson)";

    @Override
    protected List<Option> options() {
        List<Option> o = super.options();
        o.addAll(sunSpotBundles(5));
        o.add(reactorBundle("org.tinysep.sunspot.person", 5));
        o.add(reactorBundle("org.tinysep.helpbutton", 5));
        return o;
    }

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts");
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.alerts", Map.of("contacts", FIRST, "repeatMinutes", "10", "escalateMinutes", "15",
                "summaryTime", "", "timeZone", "UTC"));
        configs.put("org.tinysep.helpbutton", Map.of("holdMillis", "1000", "cancelSeconds", "10", "timeZone", "UTC"));
        return configs;
    }

    /** A person node: real frames, one per datagram, from its own socket. */
    private static final class PersonNode implements AutoCloseable {
        final SunSpotAddress address;
        final DatagramSocket socket;
        final InetSocketAddress radio;

        PersonNode(String address, int port) throws IOException {
            this.address = SunSpotAddress.parse(address);
            this.socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
            this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), port);
        }

        void send(SunSpotPayload p) throws IOException {
            byte[] frame = SunSpotCodec.encode(SunSpotFrame.of(address, SunSpotPayloads.encode(p)));
            socket.send(new DatagramPacket(frame, frame.length, radio));
        }

        @Override
        public void close() {
            socket.close();
        }
    }

    private static final MovementSummaryReport STILL =
            new MovementSummaryReport(2000, new AccelerationSample(10, -990, 60), 4, 1000);

    private List<String> events(String origin) {
        return awaitService(EventLog.class, null, TIMEOUT).recent(100_000).stream()
                .filter(e -> e.origin().equals(origin)).map(EventEntry::message).toList();
    }

    /** Sends a switch change and waits until the node's device has taken it (so its arrival time is known). */
    private void button(PersonNode node, Device device, boolean pressed, Instant now) throws IOException {
        node.send(new ButtonReport(1, pressed));
        String expected = "switch 1 " + (pressed ? "pressed" : "released") + " at " + now;
        await(TIMEOUT, () -> parameter(device, "lastButton").equals(expected), expected);
    }

    @Test
    public void holdingTheSwitchCallsForHelpAtOnceAndASecondPressCancelsIt() throws Exception {
        try (SmtpSink sink = new SmtpSink().start(); SyncPeer sync = sync();
                PersonNode node = new PersonNode(ANNA, udpPortOf("BusRadioSunSpot"))) {
            mailTo(sink, CARER);
            AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
            Instant t = tomorrow();
            sync.tickDone(t);
            node.send(STILL);
            String filter = "(tinysep.node.address=" + ANNA + ")";
            awaitService(PersonNodeProvider.class, filter, TIMEOUT);
            Device device = awaitService(Device.class, "(&" + filter + PERSON_DEVICE + ")", TIMEOUT);
            device.setParameter("person", "Anna");

            // a short press: logged, no call (and proof that the help button listens to the node)
            button(node, device, true, t);
            sync.tickDone(t.plusMillis(400));
            button(node, device, false, t.plusMillis(400));
            await(TIMEOUT, () -> events("HelpButton").contains("Anna pressed switch 1 for only 0.4 s: not a help call "
                    + "(the switch must be held for at least 1.0 s)"), "the short press logged");
            assertTrue(alerts.open().isEmpty());

            // held: the call goes out at the first platform time at which the switch has been held 1 s
            Instant press = t.plusSeconds(10);
            sync.tickDone(press);
            button(node, device, true, press);
            sync.tickDone(press.plusMillis(900));
            assertTrue("held 0.9 s: no call yet", alerts.open().isEmpty());
            sync.tickDone(press.plusMillis(1000));
            await(TIMEOUT, () -> alerts.open().size() == 1, "one open alert");
            Alert a = alerts.open().get(0);
            assertEquals(AlertKind.HELP, a.kind());
            assertEquals("help:" + ANNA, a.source());
            assertEquals("TinySEP: Anna asks for help (help button, " + press.plusSeconds(1).toString().substring(11, 19)
                    + ")", a.subject());
            Notification first = a.notifications().get(0);
            assertEquals(List.of(FIRST), first.to());
            Duration delay = Duration.between(press, first.at());
            log.info("help button: press frame at {}, first notification handed to the Mail Manager at {} ({} ms "
                    + "after the press, hold 1000 ms)", press, first.at(), delay.toMillis());
            assertTrue("first notification within the hold + 1 s of the press frame's arrival: " + delay,
                    delay.compareTo(Duration.ofMillis(2000)) <= 0);
            assertEquals("handed over at the instant the hold completed", press.plusMillis(1000), first.at());
            assertTrue("the first message mailed", sink.await(1, TIMEOUT));
            assertEquals(List.of(FIRST), sink.messages().get(0).to());

            sync.tickDone(press.plusMillis(1500));
            button(node, device, false, press.plusMillis(1500));
            assertEquals("the release makes no second call", 1, alerts.recent(10).size());

            // pressed by mistake: a second press within 10 s cancels, everyone told gets an all clear
            Instant again = press.plusSeconds(6);
            sync.tickDone(again);
            button(node, device, true, again);
            await(TIMEOUT, () -> alerts.alert(a.id()).orElseThrow().state() == AlertState.CLEARED, "cleared");
            Alert done = alerts.alert(a.id()).orElseThrow();
            assertTrue(done.closedBy(), done.closedBy().startsWith("pressed by mistake: Anna pressed the switch "
                    + "again at "));
            assertTrue("the all clear mailed", sink.await(2, TIMEOUT));
            sync.tickDone(again.plusSeconds(3));
            button(node, device, false, again.plusSeconds(3));
            assertTrue("the cancelling press calls nothing", alerts.open().isEmpty());
            List<String> steps = events("HelpButton");
            assertTrue(steps.toString(), steps.stream().anyMatch(s -> s.startsWith("help call from Anna at ")
                    && s.contains("raised as alert " + a.id() + " through the alert service")));
            assertTrue(steps.toString(), steps.stream().anyMatch(s -> s.startsWith("help call from Anna of ")
                    && s.contains("cancelled, pressed by mistake")));
        }
    }

    @Test
    public void aButtonFromANodeThatIsARoomSensorRaisesNothingAndIsReported() throws Exception {
        String roomNode = "0014.4F01.0000.0B0B";
        try (SyncPeer sync = sync(); PersonNode node = new PersonNode(roomNode, udpPortOf("BusRadioSunSpot"))) {
            AlertService alerts = awaitService(AlertService.class, null, TIMEOUT);
            Instant t = tomorrow();
            sync.tickDone(t);
            node.send(new MovementDetection(true)); // a room movement sensor ...
            awaitService(Device.class, "(&(tinysep.node.address=" + roomNode + ")(tinysep.node.type=movement))",
                    TIMEOUT);
            node.send(new ButtonReport(1, true)); // ... that now sends a (forged) button report
            Device device = awaitService(Device.class, "(&(tinysep.node.address=" + roomNode + ")" + PERSON_DEVICE
                    + ")", TIMEOUT);
            String origin = device.uid();
            node.send(new ButtonReport(1, true));
            await(TIMEOUT, () -> events(origin).stream().anyMatch(s -> s.startsWith("switch 1 pressed on a node that "
                    + "also reports as movement: not taken as a person's switch, nothing is raised")), "reported");
            sync.tickDone(t.plusSeconds(5));
            node.send(new ButtonReport(1, false));
            await(TIMEOUT, () -> !parameter(device, "ignoredReports").equals("0")
                    && !parameter(device, "ignoredReports").equals("1"), "the reports counted");
            sync.tickDone(t.plusSeconds(6));
            assertTrue("no help alert", alerts.recent(10).isEmpty());
            assertTrue(events("HelpButton").isEmpty());
        }
    }
}

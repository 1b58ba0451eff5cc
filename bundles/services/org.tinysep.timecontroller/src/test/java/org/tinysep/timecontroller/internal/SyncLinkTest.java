package org.tinysep.timecontroller.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.TimeControllerListener;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;
import org.tinysep.link.sync.SyncSecret;

/**
 * The synchroniser link end to end with real UDP sockets on 127.0.0.1: a synchroniser socket talks to the link,
 * the protocol drives a clock with listeners.
 */
class SyncLinkTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");
    static final byte[] KEY = "0123456789abcdef0123456789abcdef".getBytes(StandardCharsets.US_ASCII);

    private final List<Instant> advanced = new CopyOnWriteArrayList<>();
    private RecordingLogs logs;
    private ClockService clock;
    private SyncProtocol protocol;
    private SyncLink link;
    private DatagramSocket synchroniser;
    private InetSocketAddress platform;
    private SyncAuth auth;
    private final List<String> byes = new CopyOnWriteArrayList<>();

    @BeforeEach
    void open() throws IOException {
        logs = new RecordingLogs(() -> T0);
        DriverContext context = new DriverContext(null, "driver-uid", "TimeController", logs.reporter(),
                new PlatformClock(() -> T0));
        clock = new ClockService("clock-uid", new SyncClock(() -> T0, ClockMode.EXTERNAL));
        clock.connect((source, now) -> advanced.add(now));
        auth = new SyncAuth(KEY, null);
        protocol = new SyncProtocol(context, clock, auth, () -> {
            byes.add("bye");
            clock.switchTo(ClockMode.REAL, t -> { });
        });
        link = SyncLink.open("127.0.0.1", 0);
        link.start(protocol);
        synchroniser = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        synchroniser.setSoTimeout(5000);
        platform = new InetSocketAddress(InetAddress.getLoopbackAddress(), link.localPort());
    }

    @AfterEach
    void close() {
        synchroniser.close();
        link.close();
    }

    private String ask(String request) throws IOException {
        byte[] b = request.getBytes(StandardCharsets.ISO_8859_1);
        synchroniser.send(new DatagramPacket(b, b.length, platform));
        DatagramPacket in = new DatagramPacket(new byte[512], 512);
        synchroniser.receive(in);
        return new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII);
    }

    private String session;

    /** @return this synchroniser socket's session, from a HELLO (sent once) */
    private String session() throws IOException {
        if (session == null) {
            session = ask("HELLO").split(" ")[3];
        }
        return session;
    }

    /** @return {@code request} with the HMAC of a synchroniser that knows {@code key}, for this socket's session */
    private String signed(String request, byte[] key) throws IOException {
        return request + " " + SyncSecret.hmac(key, session(), request);
    }

    /** Sends a request signed with the platform's key; the unsigned requests of this test are sent with ask. */
    private String askSigned(String request) throws IOException {
        return ask(signed(request, KEY));
    }

    @Test
    void helloIsAnsweredWithTheClockModeAndTheSendersSession() throws Exception {
        String welcome = ask("HELLO");
        assertTrue(welcome.matches("WELCOME 2026-11-22T10:00:00Z EXTERNAL [0-9a-f]{16}"), welcome);
        assertEquals(welcome, ask("HELLO"), "the same session for the same sender");
        try (DatagramSocket other = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            other.setSoTimeout(5000);
            byte[] b = "HELLO".getBytes(StandardCharsets.US_ASCII);
            other.send(new DatagramPacket(b, b.length, platform));
            DatagramPacket in = new DatagramPacket(new byte[512], 512);
            other.receive(in);
            String theirs = new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII);
            assertTrue(!theirs.split(" ")[3].equals(welcome.split(" ")[3]), "another sender, another session");
        }
        assertEquals(3, protocol.received());
    }

    /**
     * HELLOs from {@code n} sockets on 127.0.0.1, all open at once (so each has its own port: a closed socket's
     * port may be handed out again), each WELCOME awaited.
     */
    private void hellosFromOtherPorts(int n) throws IOException {
        List<DatagramSocket> others = new java.util.ArrayList<>();
        try {
            for (int i = 0; i < n; i++) {
                DatagramSocket other = new DatagramSocket(0, InetAddress.getLoopbackAddress());
                others.add(other);
                other.setSoTimeout(5000);
                byte[] b = "HELLO".getBytes(StandardCharsets.US_ASCII);
                other.send(new DatagramPacket(b, b.length, platform));
                DatagramPacket in = new DatagramPacket(new byte[512], 512);
                other.receive(in);
                assertTrue(new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII)
                        .startsWith("WELCOME"));
            }
        } finally {
            others.forEach(DatagramSocket::close);
        }
    }

    @Test
    void aFloodOfHellosFromOtherPortsDoesNotEvictTheSynchronisersSession() throws Exception {
        assertEquals("DONE 1 2026-11-22T11:00:00Z", askSigned("TICK 1 2026-11-22T11:00:00Z"));
        hellosFromOtherPorts(SyncAuth.MAX_SESSIONS + 44); // 300 HELLOs, each from its own port
        assertEquals("DONE 2 2026-11-22T11:00:01Z", askSigned("TICK 2 2026-11-22T11:00:01Z"),
                "the live, signed session survives the flood");
        assertEquals("WELCOME 2026-11-22T11:00:01Z EXTERNAL " + session(), ask("HELLO"), "and keeps its value");
    }

    @Test
    void sessionsThatOnlySaidHelloAreStillBounded() throws Exception {
        session(); // HELLO, never a signed request
        hellosFromOtherPorts(SyncAuth.MAX_SESSIONS);
        String answer = askSigned("TICK 1 2026-11-22T11:00:00Z");
        assertTrue(answer.startsWith("ERROR 1 unauthorized no session for"),
                "the oldest unauthenticated session made room: " + answer);
    }

    @Test
    void aTickFromASenderWithoutTheKeyIsRefused() throws Exception {
        byte[] otherKey = "not-the-platform-key-0123456789".getBytes(StandardCharsets.US_ASCII);
        assertTrue(ask("TICK 0 2026-11-22T11:00:00Z " + "0".repeat(64)).startsWith(
                "ERROR 0 unauthorized no session for 127.0.0.1:"), "no HELLO yet");
        assertTrue(ask("TICK 1 2026-11-22T11:00:00Z").startsWith("ERROR 1 unauthorized TICK without an HMAC"));
        assertTrue(ask(signed("TICK 2 2026-11-22T11:00:00Z", otherKey)).startsWith("ERROR 2 unauthorized wrong HMAC"));
        assertTrue(ask("TICK 3 2026-11-22T11:00:00Z " + "0".repeat(64)).startsWith("ERROR 3 unauthorized "));
        assertTrue(ask("BYE 4").startsWith("ERROR 4 unauthorized "));
        assertEquals(T0, clock.now(), "the clock did not move");
        assertEquals(ClockMode.EXTERNAL, clock.mode());
        assertEquals(List.of(), advanced);
        assertEquals(5, protocol.rejected("unauthorized"));
        assertEquals(1, logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM
                && e.message().contains("unauthorized")).count(), "one PROBLEM, then only counted: " + logs.events());
        assertEquals("DONE 5 2026-11-22T11:00:00Z", askSigned("TICK 5 2026-11-22T11:00:00Z"), "the key holder is served");
    }

    @Test
    void offLoopbackOnlyAllowedSynchronisersMayDriveTheClockEvenWithTheKey() throws Exception {
        DriverContext context = new DriverContext(null, "driver-uid", "TimeController", logs.reporter(),
                new PlatformClock(() -> T0));
        SyncProtocol guarded = new SyncProtocol(context, clock, auth, () -> { },
                org.tinysep.device.support.intake.SourceGate.of("0.0.0.0", "127.0.0.1", 0));
        try (SyncLink open = SyncLink.open("0.0.0.0", 0);
                DatagramSocket stranger = new DatagramSocket(0, InetAddress.getByName("127.0.0.2"))) {
            open.start(guarded);
            stranger.setSoTimeout(5000);
            InetSocketAddress to = new InetSocketAddress(InetAddress.getLoopbackAddress(), open.localPort());
            for (String request : List.of("HELLO", "TICK 1 2026-11-22T12:00:00Z " + "0".repeat(64))) {
                byte[] b = request.getBytes(StandardCharsets.US_ASCII);
                stranger.send(new DatagramPacket(b, b.length, to));
                DatagramPacket in = new DatagramPacket(new byte[512], 512);
                stranger.receive(in);
                String answer = new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII);
                assertEquals("ERROR - forbidden 127.0.0.2 is not an allowed time synchroniser (syncAllowedSources)",
                        answer);
            }
            assertEquals(2, guarded.rejected("forbidden"));
            assertEquals(T0, clock.now(), "the clock did not move");
            assertEquals(List.of(), advanced);
            platform = to; // the allowed synchroniser (127.0.0.1) is served as before
            assertEquals("DONE 3 2026-11-22T10:00:02Z", askSigned("TICK 3 2026-11-22T10:00:02Z"));
        }
    }

    @Test
    void aCapturedTickCannotBeReplayed() throws Exception {
        String first = signed("TICK 7 2026-11-22T10:00:01Z", KEY);
        assertEquals("DONE 7 2026-11-22T10:00:01Z", ask(first));
        assertEquals("DONE 7 2026-11-22T10:00:01Z", ask(first), "a resend (lost DONE) is answered, not fired");
        assertEquals("DONE 8 2026-11-22T10:00:05Z", askSigned("TICK 8 2026-11-22T10:00:05Z"));
        assertTrue(ask(first).startsWith("ERROR 7 replayed sequence number 7 is not above the last accepted 8"));
        assertTrue(askSigned("TICK 8 2026-11-22T10:00:09Z").startsWith("ERROR 8 replayed "), "same seq, other time");
        assertEquals(List.of(T0.plusSeconds(1), T0.plusSeconds(5)), advanced);
        String captured = signed("TICK 99 2026-11-22T10:00:10Z", KEY);
        try (DatagramSocket attacker = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            attacker.setSoTimeout(5000);
            for (String request : List.of("HELLO", captured)) {
                byte[] b = request.getBytes(StandardCharsets.US_ASCII);
                attacker.send(new DatagramPacket(b, b.length, platform));
                DatagramPacket in = new DatagramPacket(new byte[512], 512);
                attacker.receive(in);
                String answer = new String(in.getData(), 0, in.getLength(), StandardCharsets.US_ASCII);
                assertTrue(answer.startsWith(request.equals("HELLO") ? "WELCOME " : "ERROR 99 unauthorized wrong HMAC"),
                        "a TICK signed for another sender's session is worthless from here: " + answer);
            }
        }
        assertEquals(List.of(T0.plusSeconds(1), T0.plusSeconds(5)), advanced);
    }

    @Test
    void byeReturnsTheClockToRealTime() throws Exception {
        assertEquals("DONE 1 2026-11-22T10:00:03Z", askSigned("TICK 1 2026-11-22T10:00:03Z"));
        assertEquals("DONE 2 " + T0, askSigned("BYE 2"));
        assertEquals(List.of("bye"), byes);
        assertEquals(ClockMode.REAL, clock.mode());
        assertTrue(askSigned("TICK 3 2026-11-22T10:00:04Z").startsWith("ERROR 3 not-external "));
    }

    @Test
    void withoutAKeyEveryTickIsRefused() throws Exception {
        link.close();
        SyncProtocol keyless = new SyncProtocol(new DriverContext(null, "driver-uid", "TimeController",
                logs.reporter(), new PlatformClock(() -> T0)), clock, new SyncAuth(null, "cannot read /x/sync.key"),
                () -> { });
        link = SyncLink.open("127.0.0.1", 0);
        link.start(keyless);
        platform = new InetSocketAddress(InetAddress.getLoopbackAddress(), link.localPort());
        assertTrue(ask("TICK 1 2026-11-22T10:00:01Z 00").startsWith(
                "ERROR 1 unauthorized the platform has no synchroniser key (cannot read /x/sync.key)"));
        assertEquals(T0, clock.now());
    }

    @Test
    void eachTickRunsEveryListenerBeforeDoneIsSent() throws Exception {
        List<Instant> second = new CopyOnWriteArrayList<>();
        clock.connect((source, now) -> {
            throw new IllegalStateException("a broken listener");
        });
        clock.connect((source, now) -> second.add(now));
        for (int i = 1; i <= 50; i++) {
            Instant t = T0.plusSeconds(i);
            assertEquals("DONE " + i + " " + t, askSigned("TICK " + i + " " + t));
            assertEquals(t, advanced.get(advanced.size() - 1), "already advanced when DONE arrived");
            assertEquals(i, second.size(), "the listener after the broken one ran too");
        }
        assertEquals(50, protocol.ticks());
        assertEquals(T0.plusSeconds(50), clock.now());
    }

    @Test
    void badDatagramsGetErrorAnswersAreCountedAndTheLinkGoesOn() throws Exception {
        assertEquals("DONE 1 2026-11-22T10:00:10Z", askSigned("TICK 1 2026-11-22T10:00:10Z"));
        assertTrue(askSigned("TICK 2 2026-11-22T10:00:09Z").startsWith("ERROR 2 backwards 2026-11-22T10:00:09Z is before"));
        assertTrue(ask("TICK 3 noon").startsWith("ERROR 3 malformed "));
        assertTrue(ask("TOCK").startsWith("ERROR - unknown-command "));
        assertTrue(ask("\u00ff\u0000").startsWith("ERROR - malformed "));
        assertTrue(ask("HELLO " + "x".repeat(600)).startsWith("ERROR - too-long "));
        assertTrue(askSigned("TICK 4 2026-11-22T10:00:10Z").startsWith("DONE 4 "), "the link still works");
        assertEquals(List.of(T0.plusSeconds(10), T0.plusSeconds(10)), advanced);
        assertEquals(1, protocol.rejected("backwards"));
        assertEquals(2, protocol.rejected("malformed"));
        assertEquals(1, protocol.rejected("unknown-command"));
        assertEquals(1, protocol.rejected("too-long"));
        assertEquals(8, protocol.received(), "7 requests and the HELLO for the session");
        long problems = logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM).count();
        assertEquals(4, problems, "the first of each code only: " + logs.events());
        assertEquals(5, logs.packets().size(), "every rejected datagram is in the packet log");
    }

    @Test
    void ticksAreRefusedInRealModeAndAcceptedAfterTheSwitch() throws Exception {
        List<String> modes = new CopyOnWriteArrayList<>();
        clock.connect(new TimeControllerListener() {
            @Override
            public void timeAdvanced(TimeControllerProvider source, Instant now) {
            }

            @Override
            public void modeChanged(TimeControllerProvider source, ClockMode mode, Instant at) {
                modes.add(mode + "@" + at);
            }
        });
        List<Instant> before = new CopyOnWriteArrayList<>();
        assertTrue(clock.switchTo(ClockMode.REAL, before::add).isPresent());
        assertTrue(askSigned("TICK 1 2026-11-22T10:00:01Z").startsWith("ERROR 1 not-external "));
        assertTrue(ask("HELLO").contains(" REAL "));
        assertTrue(clock.switchTo(ClockMode.EXTERNAL, before::add).isPresent());
        assertTrue(clock.switchTo(ClockMode.EXTERNAL, before::add).isEmpty(), "no change, no announcement");
        assertEquals("DONE 2 2026-11-22T10:00:01Z", askSigned("TICK 2 2026-11-22T10:00:01Z"));
        assertEquals(List.of("REAL@" + T0, "EXTERNAL@" + T0), modes);
        assertEquals(List.of(T0, T0), before);
    }

    @Test
    void aRetransmittedTickIsAnsweredAgainWithoutFiringTwice() throws Exception {
        assertEquals("DONE 9 2026-11-22T10:00:01Z", askSigned("TICK 9 2026-11-22T10:00:01Z"));
        assertEquals("DONE 9 2026-11-22T10:00:01Z", askSigned("TICK 9 2026-11-22T10:00:01Z"));
        assertEquals(1, advanced.size());
    }

    @Test
    void closingStopsAnswering() throws Exception {
        assertTrue(ask("HELLO").startsWith("WELCOME"));
        link.close();
        synchroniser.setSoTimeout(300);
        byte[] b = "HELLO".getBytes(StandardCharsets.US_ASCII);
        synchroniser.send(new DatagramPacket(b, b.length, platform));
        try {
            synchroniser.receive(new DatagramPacket(new byte[64], 64));
            throw new AssertionError("answered after close");
        } catch (SocketTimeoutException | java.net.PortUnreachableException expected) {
            // nothing answers any more
        }
    }
}

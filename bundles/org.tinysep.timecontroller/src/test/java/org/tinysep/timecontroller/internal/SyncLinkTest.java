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
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.PlatformClock;
import org.tinysep.device.support.RecordingLogs;

/**
 * The synchroniser link end to end with real UDP sockets on 127.0.0.1: a synchroniser socket talks to the link,
 * the protocol drives a clock with listeners.
 */
class SyncLinkTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    private final List<Instant> advanced = new CopyOnWriteArrayList<>();
    private RecordingLogs logs;
    private ClockService clock;
    private SyncProtocol protocol;
    private SyncLink link;
    private DatagramSocket synchroniser;
    private InetSocketAddress platform;

    @BeforeEach
    void open() throws IOException {
        logs = new RecordingLogs(() -> T0);
        DriverContext context = new DriverContext(null, "driver-uid", "TimeController", logs.reporter(),
                new PlatformClock(() -> T0));
        clock = new ClockService("clock-uid", new SyncClock(() -> T0, ClockMode.EXTERNAL));
        clock.connect((source, now) -> advanced.add(now));
        protocol = new SyncProtocol(context, clock);
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

    @Test
    void helloIsAnsweredWithTheClockAndMode() throws Exception {
        assertEquals("WELCOME 2026-11-22T10:00:00Z EXTERNAL", ask("HELLO"));
        assertEquals(1, protocol.received());
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
            assertEquals("DONE " + i + " " + t, ask("TICK " + i + " " + t));
            assertEquals(t, advanced.get(advanced.size() - 1), "already advanced when DONE arrived");
            assertEquals(i, second.size(), "the listener after the broken one ran too");
        }
        assertEquals(50, protocol.ticks());
        assertEquals(T0.plusSeconds(50), clock.now());
    }

    @Test
    void badDatagramsGetErrorAnswersAreCountedAndTheLinkGoesOn() throws Exception {
        assertEquals("DONE 1 2026-11-22T10:00:10Z", ask("TICK 1 2026-11-22T10:00:10Z"));
        assertTrue(ask("TICK 2 2026-11-22T10:00:09Z").startsWith("ERROR 2 backwards 2026-11-22T10:00:09Z is before"));
        assertTrue(ask("TICK 3 noon").startsWith("ERROR 3 malformed "));
        assertTrue(ask("TOCK").startsWith("ERROR - unknown-command "));
        assertTrue(ask("\u00ff\u0000").startsWith("ERROR - malformed "));
        assertTrue(ask("HELLO " + "x".repeat(600)).startsWith("ERROR - too-long "));
        assertTrue(ask("TICK 4 2026-11-22T10:00:10Z").startsWith("DONE 4 "), "the link still works");
        assertEquals(List.of(T0.plusSeconds(10), T0.plusSeconds(10)), advanced);
        assertEquals(1, protocol.rejected("backwards"));
        assertEquals(2, protocol.rejected("malformed"));
        assertEquals(1, protocol.rejected("unknown-command"));
        assertEquals(1, protocol.rejected("too-long"));
        assertEquals(7, protocol.received());
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
        assertTrue(ask("TICK 1 2026-11-22T10:00:01Z").startsWith("ERROR 1 not-external "));
        assertTrue(ask("HELLO").endsWith(" REAL"));
        assertTrue(clock.switchTo(ClockMode.EXTERNAL, before::add).isPresent());
        assertTrue(clock.switchTo(ClockMode.EXTERNAL, before::add).isEmpty(), "no change, no announcement");
        assertEquals("DONE 1 2026-11-22T10:00:01Z", ask("TICK 1 2026-11-22T10:00:01Z"));
        assertEquals(List.of("REAL@" + T0, "EXTERNAL@" + T0), modes);
        assertEquals(List.of(T0, T0), before);
    }

    @Test
    void aRetransmittedTickIsAnsweredAgainWithoutFiringTwice() throws Exception {
        assertEquals("DONE 9 2026-11-22T10:00:01Z", ask("TICK 9 2026-11-22T10:00:01Z"));
        assertEquals("DONE 9 2026-11-22T10:00:01Z", ask("TICK 9 2026-11-22T10:00:01Z"));
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

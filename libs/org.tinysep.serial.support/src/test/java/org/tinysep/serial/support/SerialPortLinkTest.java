package org.tinysep.serial.support;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.testsupport.serial.PtyPeer;
import org.tinysep.testsupport.serial.SocatPair;
import org.tinysep.testsupport.wait.Await;

/** The link against real socat pseudo-terminal pairs: bytes both ways, a vanishing port, reopening by itself. */
class SerialPortLinkTest {

    private static final Duration REOPEN = Duration.ofMillis(100);

    @TempDir
    Path dir;
    private SocatPair pair;
    private SerialPortLink link;
    private final LinkRecorder recorder = new LinkRecorder();

    @BeforeEach
    void socat() throws Exception {
        pair = new SocatPair(dir).start();
    }

    @AfterEach
    void stop() throws Exception {
        if (link != null) {
            link.close();
        }
        pair.kill();
    }

    private SerialPortLink link(Path port, SerialPortLink.Listener listener) {
        link = new SerialPortLink(port.toString(), 115200, REOPEN, "test-link", listener);
        link.start();
        return link;
    }

    @Test
    void bytesTravelBothWays() throws Exception {
        link(pair.a(), recorder);
        assertEquals("opened " + pair.a(), recorder.next());
        assertTrue(link.isOpen());
        assertEquals("open at 115200 baud", link.state());

        try (PtyPeer peer = new PtyPeer(pair.b())) {
            byte[] hello = "hello from the node".getBytes(StandardCharsets.US_ASCII);
            peer.write(hello);
            await(() -> recorder.bytes().length >= hello.length, "bytes at the link");
            assertArrayEquals(hello, recorder.bytes());

            CompletableFuture<String> outcome = new CompletableFuture<>();
            byte[] command = {4, (byte) 0xA1, 0, 20, 1, 0, (byte) 0xD0, 4, 5, 2, 0, 40};
            link.write(command, (data, failure) -> outcome.complete(failure == null ? "ok" : failure));
            assertArrayEquals(command, peer.read(command.length));
            assertEquals("ok", outcome.get(5, TimeUnit.SECONDS));
        }
        assertEquals(12, link.bytesWritten());
        assertEquals(19, link.bytesRead());
        assertEquals(0, link.writeFailures());
    }

    @Test
    void aVanishedPortIsReportedLostAndReopenedWhenItComesBack() throws Exception {
        link(pair.a(), recorder);
        assertEquals("opened " + pair.a(), recorder.next());

        pair.kill();
        String lost = recorder.next();
        assertTrue(lost.startsWith("lost " + pair.a() + ": read failed"), lost);
        await(() -> !link.isOpen(), "the link to count as closed");
        assertTrue(link.state().matches("(lost|missing) \\(.*\\), (reopening|retrying) every 100 ms"), link.state());

        CompletableFuture<String> dropped = new CompletableFuture<>();
        link.write(new byte[] {1, 2, 3}, (data, failure) -> dropped.complete(failure));
        assertTrue(dropped.get(5, TimeUnit.SECONDS).startsWith("not sent: port is not open ("));
        assertEquals(1, link.writeFailures());

        pair.start(); // new pseudo-terminals behind the same link paths
        assertEquals("opened " + pair.a(), recorder.next());
        try (PtyPeer peer = new PtyPeer(pair.b())) {
            peer.write(new byte[] {42});
            await(() -> recorder.bytes().length == 1, "bytes after the reopen");
            link.write(new byte[] {7, 7});
            assertArrayEquals(new byte[] {7, 7}, peer.read(2));
        }
        assertEquals(List.of("opened " + pair.a(), lost, "opened " + pair.a()), recorder.all,
                "one lost per outage, however many reopen attempts failed");
    }

    @Test
    void aPortMissingAtStartIsReportedOnceAndOpenedWhenItAppears() throws Exception {
        pair.kill();
        link(pair.a(), recorder);
        assertEquals("lost " + pair.a() + ": cannot open: no such port", recorder.next());
        assertFalse(link.isOpen());
        await(() -> link.state().startsWith("missing (no such port), retrying every 100 ms"), "the state");

        pair.start();
        assertEquals("opened " + pair.a(), recorder.next());
        assertEquals(2, recorder.all.size());
    }

    @Test
    void aThrowingListenerDoesNotStopTheLink() throws Exception {
        BlockingQueue<Integer> seen = new LinkedBlockingQueue<>();
        link(pair.a(), new SerialPortLink.Listener() {
            @Override
            public void bytes(byte[] buf, int len) {
                for (int i = 0; i < len; i++) {
                    seen.add((int) buf[i]);
                }
                throw new IllegalStateException("listener bug");
            }

            @Override
            public void opened(String port) {
                throw new IllegalStateException("listener bug");
            }

            @Override
            public void lost(String port, String reason) {
            }
        });
        await(link::isOpen, "the port to open");
        try (PtyPeer peer = new PtyPeer(pair.b())) {
            peer.write(new byte[] {1});
            assertEquals(1, seen.poll(5, TimeUnit.SECONDS));
            peer.write(new byte[] {2});
            assertEquals(2, seen.poll(5, TimeUnit.SECONDS));
        }
    }

    @Test
    void closeStopsReadingWritingAndReopening() throws Exception {
        link(pair.a(), recorder);
        assertEquals("opened " + pair.a(), recorder.next());
        link.close();

        assertFalse(link.isOpen());
        assertEquals("closed", link.state());
        CompletableFuture<String> dropped = new CompletableFuture<>();
        link.write(new byte[] {1}, (data, failure) -> dropped.complete(failure));
        assertTrue(dropped.get(1, TimeUnit.SECONDS).startsWith("not sent"));
        await(() -> Thread.getAllStackTraces().keySet().stream()
                .noneMatch(t -> t.getName().startsWith("test-link-")), "the link's threads to end");

        pair.kill();
        pair.start();
        assertNull(recorder.events.poll(3 * REOPEN.toMillis(), TimeUnit.MILLISECONDS), "no reopen after close");
    }

    @Test
    void badArgumentsAreRefusedAtConstruction() {
        SerialPortLink.Listener l = recorder;
        assertEquals("baud rate must be positive, was 0", assertThrowsIae(() ->
                new SerialPortLink("/dev/null", 0, REOPEN, "x", l)));
        assertEquals("reopenEvery must be positive, was PT0S", assertThrowsIae(() ->
                new SerialPortLink("/dev/null", 9600, Duration.ZERO, "x", l)));
    }

    private static String assertThrowsIae(Runnable r) {
        try {
            r.run();
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
        return fail("no IllegalArgumentException");
    }

    static void await(BooleanSupplier condition, String what) throws InterruptedException {
        Await.until(condition, what);
    }
}

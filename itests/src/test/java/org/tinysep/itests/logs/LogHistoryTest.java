package org.tinysep.itests.logs;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.ops4j.pax.exam.CoreOptions.frameworkProperty;
import static org.tinysep.amica.protocol.AmicaNodeType.MOVEMENT;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.Option;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.osgi.framework.Bundle;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.itests.TinySepTestSupport;
import org.tinysep.itests.Topology;

/**
 * Issue 6 point 6 (thesis 3.8): the event and packet logs keep a history on disk under {@code ${tinysep.var}/log},
 * survive a restart of the device manager bundle, and the shell searches them by time, device and kind.
 * AmICA movement frames arrive over UDP on 127.0.0.1.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class LogHistoryTest extends TinySepTestSupport {

    private static final Path VAR = Path.of("target", "itest-var", "LogHistoryTest").toAbsolutePath();

    @Override
    protected List<String> applications() {
        return FIRST_SLICE;
    }

    @Override
    protected List<Option> options() {
        deleteTree(VAR);
        List<Option> o = super.options();
        o.add(frameworkProperty("tinysep.var").value(VAR.toString()));
        return o;
    }

    private static void deleteTree(Path root) {
        if (!Files.exists(root)) {
            return;
        }
        try (Stream<Path> all = Files.walk(root)) {
            for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        } catch (IOException e) {
            throw new IllegalStateException("cannot clean " + root, e);
        }
    }

    @Test
    public void historySurvivesARestartOfTheDeviceManagerAndIsSearchable() throws Exception {
        int port = udpPortOf(BUS);
        try (DatagramSocket node = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            int[] seq = {0};
            send(node, port, seq, new KeepAlive(120, 2900, 0x0A11, AmicaNodeType.productId(List.of(MOVEMENT)), 1));
            await(TIMEOUT, () -> Topology.of(context).contains("AmicaMovement@1.17"), "the movement device");
            String movement = Topology.uid(context, "AmicaMovement", "1.17");
            for (int i = 0; i < 5; i++) {
                send(node, port, seq, new MotionDetection(i % 2 == 0));
            }
            EventLog log = awaitService(EventLog.class, null, TIMEOUT);
            await(TIMEOUT, () -> movementEvents(log, movement).size() == 5, "5 movement events");
            long lastBefore = log.recent(1).get(0).sequence();
            List<Long> before = movementEvents(log, movement).stream().map(EventEntry::sequence).toList();

            Bundle runtime = Arrays.stream(context.getBundles())
                    .filter(b -> "org.tinysep.runtime".equals(b.getSymbolicName())).findFirst().orElseThrow();
            runtime.stop();
            Path logs = VAR.resolve("log");
            assertTrue("event files written: " + list(logs), list(logs).stream().anyMatch(f -> f.startsWith("events-")));
            assertTrue("packet files written: " + list(logs), list(logs).stream().anyMatch(f -> f.startsWith("packets-")));
            runtime.start();

            EventLog after = awaitService(EventLog.class, null, TIMEOUT);
            assertEquals("the ring shows the entries from before the restart", before,
                    movementEvents(after, movement).stream().map(EventEntry::sequence).toList());
            Instant restarted = Instant.now();
            send(node, port, seq, new MotionDetection(false)); // the device logs changes: the last one was true
            await(TIMEOUT, () -> movementEvents(after, movement).size() == 6, "the 6th movement event");
            assertTrue("numbering goes on after the restart",
                    movementEvents(after, movement).get(5).sequence() > lastBefore);

            String all = shell("tinysep:events --device " + movement + " --kind DEVICE_EVENT");
            List<String> rows = all.lines().skip(1).filter(l -> !l.isBlank()).toList();
            assertEquals(all, 6, rows.size());
            for (int i = 0; i < 5; i++) {
                assertTrue(rows.get(i), rows.get(i).startsWith(before.get(i) + " "));
            }
            assertTrue(rows.get(5), rows.get(5).endsWith("no movement"));
            String recent = shell("tinysep:events --from " + restarted + " --device " + movement
                    + " --kind DEVICE_EVENT");
            assertEquals(recent, 2, recent.lines().filter(l -> !l.isBlank()).count());
            String limited = shell("tinysep:events --device \"Movement sensor 1.17\" --limit 2 --kind device_event");
            List<String> limitedRows = limited.lines().skip(1).filter(l -> !l.isBlank()).toList();
            assertEquals(limited, List.of(rows.get(4), rows.get(5)), limitedRows);

            String packets = shell("tinysep:packets --device " + movement + " --kind RECEIVED --from -10m");
            List<String> packetRows = packets.lines().skip(1).filter(l -> !l.isBlank()).toList();
            assertEquals(packets, 7, packetRows.size()); // keep-alive, 5 motions before, 1 after the restart
            assertTrue(packets, packetRows.stream().allMatch(l -> l.contains("node 1.17 via")));
        }
    }

    private static List<String> list(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    private static List<EventEntry> movementEvents(EventLog log, String uid) {
        return log.recent(10_000).stream()
                .filter(e -> e.kind() == EventKind.DEVICE_EVENT && e.origin().equals(uid)).toList();
    }

    private static void send(DatagramSocket socket, int port, int[] seq,
            org.tinysep.amica.protocol.AmicaPayload payload) throws IOException {
        byte[] frame = AmicaCodec.encode(new AmicaFrame(1, 17, 0, seq[0]++ & 0xFF, AmicaPayloads.encode(payload)));
        socket.send(new DatagramPacket(frame, frame.length, InetAddress.getLoopbackAddress(), port));
    }
}

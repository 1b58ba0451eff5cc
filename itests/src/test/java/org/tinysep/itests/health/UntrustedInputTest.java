package org.tinysep.itests.health;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.log.PacketLog;
import org.tinysep.itests.TinySepTestSupport;

/**
 * Input the platform does not trust (issue 12.6, issue 14): the UDP bus radio bound to 0.0.0.0 takes frames only
 * from its allow-list (a sender on 127.0.0.2 is rejected and counted), caps its nodes, rate-limits a flooding
 * sender (127.0.0.3) without starving another (127.0.0.1), and keeps rejected frames out of the packet-log history
 * beyond a bounded sample while every counter stays exact.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class UntrustedInputTest extends TinySepTestSupport {

    /** RejectSampler.BURST: rejected frames kept in full before the sampling starts. */
    private static final int KEPT_IN_FULL = 500;

    @Override
    protected List<String> applications() {
        return FIRST_SLICE;
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put(UDP_PID, Map.of("port", "0", "bindAddress", "0.0.0.0", "allowedSources", "127.0.0.1, 127.0.0.3",
                "sourceRateLimit", "100", "maxNodes", "3"));
        return configs;
    }

    /** Sends frames from one local address. */
    private static final class Sender implements AutoCloseable {
        private final DatagramSocket socket;
        private final InetSocketAddress radio;
        private int seq;

        Sender(String localAddress, int port) throws IOException {
            socket = new DatagramSocket(0, InetAddress.getByName(localAddress));
            radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), port);
        }

        void send(int netgroup, int address, AmicaPayload payload) throws IOException {
            byte[] f = AmicaCodec.encode(AmicaFrame.toPlatform(new AmicaAddress(netgroup, address), seq++ & 0xFF,
                    AmicaPayloads.encode(payload)));
            socket.send(new DatagramPacket(f, f.length, radio));
        }

        @Override
        public void close() {
            socket.close();
        }
    }

    private static KeepAlive keepAlive() {
        return new KeepAlive(60, 3000, 1, AmicaNodeType.productId(List.of(AmicaNodeType.MOVEMENT)), 1);
    }

    private Map<String, String> driver() {
        Driver d = awaitService(Driver.class, "(" + DeviceProperties.DRIVER_NAME + "=" + BUS + ")", TIMEOUT);
        return d.parameters().stream().collect(Collectors.toMap(Parameter::key, Parameter::value, (a, b) -> a));
    }

    private long count(String key) {
        return Long.parseLong(driver().get(key));
    }

    /** Waits until the bus radio has taken {@code total} datagrams (a small socket buffer must not drop any). */
    private void handled(long total) {
        await(TIMEOUT, () -> count("received") >= total, total + " datagrams handled");
    }

    private long packets(String node) {
        Device d = awaitService(Device.class, "(&(" + DeviceProperties.NODE_ADDRESS + "=" + node + ")("
                + DeviceProperties.DEVICE_TYPE + "=" + BUS + "))", TIMEOUT);
        return Long.parseLong(d.parameters().stream().filter(p -> p.key().equals("packets")).findFirst()
                .orElseThrow().value());
    }

    private List<String> problems(String containing) {
        EventLog events = awaitService(EventLog.class, null, TIMEOUT);
        return events.recent(10_000).stream().filter(e -> e.kind() == EventKind.PROBLEM)
                .map(e -> e.message()).filter(m -> m.contains(containing)).toList();
    }

    @Test
    public void framesFromElsewhereAreRejectedAFloodIsLimitedAndTheHistoryStaysBounded() throws Exception {
        int port = udpPortOf(BUS);
        long sent = 0;
        try (Sender stranger = new Sender("127.0.0.2", port); Sender home = new Sender("127.0.0.1", port);
                Sender flooder = new Sender("127.0.0.3", port)) {
            // 1. allow-list: valid keep-alives from 127.0.0.2 create nothing
            for (int i = 0; i < 3000; i++) {
                stranger.send(5, 1, keepAlive());
                if (++sent % 100 == 0) {
                    handled(sent);
                }
            }
            handled(sent);
            assertEquals(3000, count("rejected.source_not_allowed"));
            assertEquals("0", driver().get("nodes"));
            assertEquals(1, problems("source 127.0.0.2 is not on the allow-list").size());
            PacketLog packets = awaitService(PacketLog.class, null, TIMEOUT);
            long kept = packets.recent(100_000).stream().filter(p -> p.note().contains("not on the allow-list"))
                    .count();
            assertTrue("rejected frames sampled in the history: " + kept, kept >= KEPT_IN_FULL
                    && kept <= KEPT_IN_FULL + 20);

            // 2. node cap: 5 new nodes from an allowed source, 3 created
            for (int a = 1; a <= 5; a++) {
                home.send(6, a, keepAlive());
            }
            handled(sent += 5);
            assertEquals("3", driver().get("nodes"));
            assertEquals(2, count("rejected.node_cap"));
            assertEquals("the total counts node_cap too (issue 25, item 8)", 3000 + 2, count("rejected"));
            assertEquals(1, problems("its limit (maxNodes = 3)").size());

            // 3. rate limit: 127.0.0.3 floods node 6.1's frames, 127.0.0.1 still gets each of node 6.2's through
            for (int i = 0; i < 2000; i++) {
                flooder.send(6, 1, new MotionDetection(true));
                if (++sent % 100 == 0) {
                    home.send(6, 2, new MotionDetection(true));
                    handled(++sent);
                }
            }
            handled(sent);
            long limited = count("rejected.rate_limited");
            assertTrue("the flood was limited: " + limited, limited > 0);
            assertEquals("the other sender was not starved", 1 + 20, packets("6.2"));
            assertEquals("every flood frame either delivered or counted", 1 + 2000, packets("6.1") + limited);
            assertEquals("every datagram counted", sent, count("received"));
            assertEquals("the total is the sum of every rejected.<reason>", 3000 + 2 + limited, count("rejected"));
            assertEquals(1, problems("source 127.0.0.3 sends faster than the per-source rate limit").size());
        }
    }
}

package org.tinysep.amica.busradio.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;

/**
 * Issue 29, item 1: what the radio's receive thread allocates per frame to name its origin in the packet log. The
 * origin of a known node by its known route was found under a new (node, route) key per frame and hashed through
 * a record's method handles; it is now found by the node's own address and its route compared. A real transport
 * hands a new but equal route object per datagram (a UDP sender's socket address), as this test does.
 */
class ReceiveCostTest {

    private final TestRadio radio = new TestRadio();
    private final String[] routes = {new String("127.0.0.1:40000"), new String("127.0.0.1:40000")};
    private long sink;

    @Test
    void theOriginOfAKnownNodeAllocatesNothingPerFrame() {
        assertNotSame(routes[0], routes[1]);
        radio.feed(TestRadio.frame(1, 17, TestRadio.keepAlive(AmicaNodeType.MOVEMENT)), routes[0]);
        AmicaAddress node = new AmicaFrame(1, 17, 0, 1, new byte[0]).sender();
        double bytes = bytesPerCall(20_000, i -> sink += radio.handler.originOf(node, routes[i & 1]).length());
        assertTrue(bytes < 16, "bytes allocated per frame to name a known node's origin: " + bytes);
        assertEquals("node 1.17 via route 127.0.0.1:40000", radio.handler.originOf(node, routes[1]));
        assertEquals("node 1.17 via route 127.0.0.1:40001", radio.handler.originOf(node, "127.0.0.1:40001"),
                "another route is named anew");
    }

    interface Work {
        void run(int i);
    }

    static double bytesPerCall(int calls, Work work) {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        for (int i = 0; i < calls; i++) {
            work.run(i);
        }
        long id = Thread.currentThread().getId();
        long before = mx.getThreadAllocatedBytes(id);
        for (int i = 0; i < calls; i++) {
            work.run(i);
        }
        return (mx.getThreadAllocatedBytes(id) - before) / (double) calls;
    }
}

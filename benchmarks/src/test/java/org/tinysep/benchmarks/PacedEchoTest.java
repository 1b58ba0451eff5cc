package org.tinysep.benchmarks;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetSocketAddress;
import java.nio.channels.DatagramChannel;
import org.junit.jupiter.api.Test;

/**
 * The latency floor is paced like the samples it is the floor of: a round trip after a pause (sleeping threads,
 * idle CPUs) is what a reaction sample pays too, not what back-to-back round trips pay.
 */
class PacedEchoTest {

    @Test
    void aPacedEchoWaitsBetweenRoundTripsAndMeasuresEachAlone() throws Exception {
        try (DatagramChannel server = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0))) {
            Bare.echoing(server);
            int port = ((InetSocketAddress) server.getLocalAddress()).getPort();
            long t0 = System.nanoTime();
            double[] paced = Latency.echo(port, 5, 60);
            long tookMillis = (System.nanoTime() - t0) / 1_000_000;
            assertEquals(5, paced.length);
            assertTrue(tookMillis >= 5 * 60, "5 round trips paced 60 ms apart took " + tookMillis + " ms");
            for (int i = 1; i < paced.length; i++) {
                assertTrue(paced[i - 1] <= paced[i], "sorted");
            }
            assertTrue(paced[4] < 60_000, "a round trip is measured without the pause: " + paced[4] + " µs");
            t0 = System.nanoTime();
            Latency.echo(port, 5);
            assertTrue((System.nanoTime() - t0) / 1_000_000 < 5 * 60, "back to back does not pause");
        }
    }
}

package org.tinysep.benchmarks;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.LockSupport;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;

/**
 * N AmICA movement nodes on one loopback socket (as the simulator's nodes, without their agents): keep-alives to
 * make them known, then motion frames round-robin at a paced rate. Node i is {@code (10 + i / 250).(1 + i % 250)}:
 * several netgroups once there are more than 250.
 */
final class Nodes implements AutoCloseable {

    private final DatagramChannel channel;
    private final InetSocketAddress target;
    private final List<ByteBuffer> motion = new ArrayList<>();
    private final List<ByteBuffer> keepAlive = new ArrayList<>();
    long sent;

    Nodes(int count, int port) throws IOException {
        channel = DatagramChannel.open();
        channel.bind(new InetSocketAddress("127.0.0.1", 0));
        channel.setOption(java.net.StandardSocketOptions.SO_SNDBUF, 1 << 20);
        target = new InetSocketAddress("127.0.0.1", port);
        int productId = AmicaNodeType.productId(List.of(AmicaNodeType.fromTypeName("movement").orElseThrow()));
        for (int i = 0; i < count; i++) {
            AmicaAddress a = address(i);
            keepAlive.add(ByteBuffer.wrap(AmicaCodec.encode(AmicaFrame.toPlatform(a, 0,
                    AmicaPayloads.encode(new KeepAlive(0, 3000, 0, productId, 1))))));
            motion.add(ByteBuffer.wrap(AmicaCodec.encode(AmicaFrame.toPlatform(a, 1,
                    AmicaPayloads.encode(new MotionDetection(true))))));
        }
    }

    static AmicaAddress address(int i) {
        return new AmicaAddress(10 + i / 250, 1 + i % 250);
    }

    /** Sends every node's keep-alive, at most {@code perSecond} a second. */
    void announce(int perSecond) throws IOException {
        blast(keepAlive, keepAlive.size(), perSecond);
    }

    /** Sends {@code frames} motion frames round-robin over the nodes at {@code perSecond}; @return wall seconds */
    double motion(long frames, int perSecond) throws IOException {
        return blast(motion, frames, perSecond);
    }

    private double blast(List<ByteBuffer> frames, long total, int perSecond) throws IOException {
        long t0 = System.nanoTime();
        long periodNanos = 1_000_000L; // pacing: each millisecond's share, sent at once
        for (long n = 0; n < total; ) {
            long due = Math.min(total, (long) ((System.nanoTime() - t0) / 1e9 * perSecond) + 1);
            while (n < due) {
                ByteBuffer b = frames.get((int) (n % frames.size()));
                b.rewind();
                channel.send(b, target);
                n++;
                sent++;
            }
            if (n < total) {
                LockSupport.parkNanos(periodNanos / 4);
            }
        }
        return (System.nanoTime() - t0) / 1e9;
    }

    @Override
    public void close() throws IOException {
        channel.close();
    }
}

package org.tinysep.benchmarks;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;

/**
 * N AmICA movement nodes on a few loopback sockets, one sender thread each (as the simulator's nodes, without their
 * agents; node i always sends from socket i mod K): keep-alives to make them known, then motion frames round-robin at
 * a paced rate shared by the senders. Node i is {@code (10 + i / 250).(1 + i % 250)}:
 * several netgroups once there are more than 250.
 */
final class Nodes implements AutoCloseable {

    /** Sender threads (each its own socket and its own share of the nodes), so the sender can outrun the receiver. */
    static final int SENDERS = Integer.getInteger("bench.senders", 2);

    private final DatagramChannel[] channels;
    private final InetSocketAddress target;
    private final List<List<ByteBuffer>> motion = new ArrayList<>();
    private final List<List<ByteBuffer>> keepAlive = new ArrayList<>();
    private final ExecutorService pool;
    final AtomicLong sentTotal = new AtomicLong();
    long sent;

    /** One sender thread (the thesis scenarios, lock-step, scale, latency background). */
    Nodes(int count, int port) throws IOException {
        this(count, port, 1);
    }

    Nodes(int count, int port, int senders) throws IOException {
        int k = Math.max(1, Math.min(senders, count));
        channels = new DatagramChannel[k];
        for (int c = 0; c < k; c++) {
            channels[c] = DatagramChannel.open();
            channels[c].bind(new InetSocketAddress("127.0.0.1", 0));
            channels[c].setOption(java.net.StandardSocketOptions.SO_SNDBUF, 1 << 20);
            motion.add(new ArrayList<>());
            keepAlive.add(new ArrayList<>());
        }
        pool = Executors.newFixedThreadPool(k, r -> {
            Thread t = new Thread(r, "bench-sender");
            t.setDaemon(true);
            return t;
        });
        target = new InetSocketAddress("127.0.0.1", port);
        int productId = AmicaNodeType.productId(List.of(AmicaNodeType.fromTypeName("movement").orElseThrow()));
        for (int i = 0; i < count; i++) {
            AmicaAddress a = address(i);
            keepAlive.get(i % k).add(ByteBuffer.wrap(AmicaCodec.encode(AmicaFrame.toPlatform(a, 0,
                    AmicaPayloads.encode(new KeepAlive(0, 3000, 0, productId, 1))))));
            motion.get(i % k).add(ByteBuffer.wrap(AmicaCodec.encode(AmicaFrame.toPlatform(a, 1,
                    AmicaPayloads.encode(new MotionDetection(true))))));
        }
    }

    /** @return sender threads (sockets) */
    int senders() {
        return channels.length;
    }

    static AmicaAddress address(int i) {
        return new AmicaAddress(10 + i / 250, 1 + i % 250);
    }

    /** Sends every node's keep-alive, at most {@code perSecond} a second. */
    void announce(int perSecond) throws IOException {
        all(c -> blast(c, keepAlive.get(c), keepAlive.get(c).size(), perSecond / (double) channels.length));
    }

    /**
     * Sends the keep-alives of nodes {@code from} (inclusive) to {@code to} at once, each node from its own socket;
     * the caller bounds how many are sent ahead of the receiver (the scale benchmark's window).
     */
    void announce(int from, int to) throws IOException {
        int k = channels.length;
        for (int i = from; i < to; i++) {
            ByteBuffer b = keepAlive.get(i % k).get(i / k);
            b.rewind();
            channels[i % k].send(b, target);
        }
        sentTotal.addAndGet(Math.max(0, to - from));
        sent = sentTotal.get();
    }

    /** Sends {@code frames} motion frames round-robin over the nodes at {@code perSecond}; @return wall seconds */
    double motion(long frames, int perSecond) throws IOException {
        long t0 = System.nanoTime();
        int k = channels.length;
        all(c -> blast(c, motion.get(c), frames / k + (c < frames % k ? 1 : 0), perSecond / (double) k));
        return (System.nanoTime() - t0) / 1e9;
    }

    private interface Job {
        void run(int channel) throws IOException;
    }

    private void all(Job job) throws IOException {
        List<Future<?>> running = new ArrayList<>();
        for (int c = 0; c < channels.length; c++) {
            int channel = c;
            running.add(pool.submit(() -> {
                job.run(channel);
                return null;
            }));
        }
        try {
            for (Future<?> f : running) {
                f.get();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        } catch (ExecutionException e) {
            throw new IOException(e.getCause());
        } finally {
            sent = sentTotal.get();
        }
    }

    private void blast(int c, List<ByteBuffer> frames, long total, double perSecond) throws IOException {
        if (frames.isEmpty()) {
            return;
        }
        DatagramChannel channel = channels[c];
        long t0 = System.nanoTime();
        long periodNanos = 1_000_000L; // pacing: each millisecond's share, sent at once
        for (long n = 0; n < total; ) {
            long due = Math.min(total, (long) ((System.nanoTime() - t0) / 1e9 * perSecond) + 1);
            long now = n;
            while (n < due) {
                ByteBuffer b = frames.get((int) (n % frames.size()));
                b.rewind();
                channel.send(b, target);
                n++;
            }
            sentTotal.addAndGet(n - now);
            if (n < total) {
                LockSupport.parkNanos(periodNanos / 4);
            }
        }
    }

    @Override
    public void close() throws IOException {
        pool.shutdownNow();
        for (DatagramChannel c : channels) {
            c.close();
        }
    }
}

package org.tinysep.itests.lifecycle;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;

/**
 * Several simulated AmICA movement nodes (netgroup 1, one UDP socket each on 127.0.0.1) that stream Motion
 * Detection frames round-robin to the bus radio at a fixed total rate, bounded by a frame count and a time limit.
 * {@link #run()} is the sending loop (run it on an executor); {@link #stop()} ends it.
 */
final class MovementFlood implements Runnable {

    private final List<DatagramSocket> sockets = new ArrayList<>();
    private final List<String> nodeIds = new ArrayList<>();
    private final List<byte[][]> frames = new ArrayList<>();
    private final InetSocketAddress radio;
    private final int framesPerSecond;
    private final long maxFrames;
    private final long maxNanos;
    private final AtomicLong sent = new AtomicLong();
    private final AtomicBoolean stop = new AtomicBoolean();

    /** @param firstAddress node addresses are {@code 1.firstAddress} … {@code 1.(firstAddress + nodes - 1)} */
    MovementFlood(int radioPort, int nodes, int firstAddress, int framesPerSecond, long maxFrames, long maxMillis)
            throws IOException {
        this.radio = new InetSocketAddress(InetAddress.getLoopbackAddress(), radioPort);
        this.framesPerSecond = framesPerSecond;
        this.maxFrames = maxFrames;
        this.maxNanos = maxMillis * 1_000_000L;
        byte[] motion = AmicaPayloads.encode(new MotionDetection(true));
        for (int i = 0; i < nodes; i++) {
            sockets.add(new DatagramSocket(0, InetAddress.getLoopbackAddress()));
            nodeIds.add("1." + (firstAddress + i));
            byte[][] bySequence = new byte[256][];
            for (int seq = 0; seq < 256; seq++) {
                bySequence[seq] = AmicaCodec.encode(new AmicaFrame(1, firstAddress + i, 0, seq, motion));
            }
            frames.add(bySequence);
        }
    }

    /** @return the node addresses, e.g. {@code 1.40} */
    List<String> nodeIds() {
        return List.copyOf(nodeIds);
    }

    /**
     * Sends one keep-alive per movement node, which makes the platform create its devices, and one of a simple
     * light at {@code 1.lightAddress} (Follow-me Light exists once there is a light to follow with).
     */
    void keepAlives(int lightAddress) throws IOException {
        int product = AmicaNodeType.productId(Set.of(AmicaNodeType.MOVEMENT));
        for (int i = 0; i < sockets.size(); i++) {
            keepAlive(sockets.get(i), Integer.parseInt(nodeIds.get(i).substring(2)), product, 1000 + i);
        }
        keepAlive(sockets.get(0), lightAddress, AmicaNodeType.productId(Set.of(AmicaNodeType.SIMPLE_LIGHT)), 999);
    }

    private void keepAlive(DatagramSocket socket, int address, int product, long serial) throws IOException {
        byte[] ka = AmicaCodec.encode(new AmicaFrame(1, address, 0, 0,
                AmicaPayloads.encode(new KeepAlive(60, 3000, 0x0A11, product, serial))));
        socket.send(new DatagramPacket(ka, ka.length, radio));
    }

    /** @return Motion Detection frames sent so far */
    long sent() {
        return sent.get();
    }

    void stop() {
        stop.set(true);
    }

    @Override
    public void run() {
        long start = System.nanoTime();
        long period = 1_000_000_000L / framesPerSecond;
        int n = sockets.size();
        try {
            for (long i = 0; i < maxFrames && !stop.get() && System.nanoTime() - start < maxNanos; i++) {
                int node = (int) (i % n);
                byte[] frame = frames.get(node)[(int) ((i / n) & 0xFF)];
                sockets.get(node).send(new DatagramPacket(frame, frame.length, radio));
                sent.incrementAndGet();
                long due = start + (i + 1) * period;
                long ahead = due - System.nanoTime();
                if (ahead > 200_000) { // park in slices: sub-200 µs parks only add jitter
                    LockSupport.parkNanos(ahead);
                }
            }
        } catch (IOException e) {
            throw new IllegalStateException("sending failed after " + sent.get() + " frames: " + e, e);
        } finally {
            sockets.forEach(DatagramSocket::close);
        }
    }
}

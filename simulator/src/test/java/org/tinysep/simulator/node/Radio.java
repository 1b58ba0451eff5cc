package org.tinysep.simulator.node;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/** A stand-in bus radio for tests: a real UDP socket on 127.0.0.1 that collects every datagram it receives. */
final class Radio implements AutoCloseable {

    record Datagram(byte[] bytes, InetSocketAddress from) {
    }

    private final DatagramSocket socket;
    private final List<Datagram> received = new ArrayList<>();
    private final ExecutorService executor = Executors.newSingleThreadExecutor();

    Radio() throws IOException {
        socket = new DatagramSocket(0, InetAddress.getLoopbackAddress());
        socket.setReceiveBufferSize(4 << 20);
        executor.execute(this::collect);
    }

    int port() {
        return socket.getLocalPort();
    }

    private void collect() {
        byte[] buf = new byte[1024];
        while (!socket.isClosed()) {
            DatagramPacket p = new DatagramPacket(buf, buf.length);
            try {
                socket.receive(p);
            } catch (SocketException closed) {
                return;
            } catch (IOException e) {
                continue;
            }
            synchronized (received) {
                received.add(new Datagram(Arrays.copyOf(p.getData(), p.getLength()), (InetSocketAddress) p.getSocketAddress()));
                received.notifyAll();
            }
        }
    }

    void send(byte[] b, InetSocketAddress to) throws IOException {
        socket.send(new DatagramPacket(b, b.length, to));
    }

    List<Datagram> received() {
        synchronized (received) {
            return List.copyOf(received);
        }
    }

    /** Waits (up to 10 s) until {@code count} datagrams matching {@code p} arrived; returns all received so far. */
    List<Datagram> await(Predicate<Datagram> p, int count) throws InterruptedException {
        long end = System.currentTimeMillis() + 10_000;
        synchronized (received) {
            while (received.stream().filter(p).count() < count && System.currentTimeMillis() < end) {
                received.wait(100);
            }
            return List.copyOf(received);
        }
    }

    void clear() {
        synchronized (received) {
            received.clear();
        }
    }

    @Override
    public void close() throws InterruptedException {
        socket.close();
        executor.shutdownNow();
        executor.awaitTermination(5, TimeUnit.SECONDS);
    }
}

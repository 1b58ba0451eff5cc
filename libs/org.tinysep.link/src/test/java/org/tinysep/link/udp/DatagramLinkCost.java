package org.tinysep.link.udp;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.stream.Stream;

/**
 * The receive thread's cost per datagram, a {@link DatagramLink} against a bare blocking {@link DatagramSocket}
 * receive loop (the floor) in the same run, on 127.0.0.1. Not a test: run by hand, e.g.
 * {@code java -cp target/classes:target/test-classes:<slf4j-api> org.tinysep.link.udp.DatagramLinkCost
 * 1000,10000,50000 3}. Arguments: rates (datagrams/s), seconds a step, sender sockets (datagrams alternate between
 * them), seconds to wait first (to attach {@code strace -ff -p <pid>} or {@code perf stat --per-thread -p <pid>}).
 * <p>
 * Each step: a receiver (thread {@code link-<rate>} or {@code floor-<rate>}), 20,000 warm-up datagrams, then
 * {@code rate x seconds} datagrams paced by one sender thread (it parks until each is due, so at high rates a few go
 * at once), at most 5 s more to receive them. As the AmICA radio, the link runs with a tick that drains it every
 * second from another thread. Printed per step: datagrams sent and received, the receive thread's CPU per datagram
 * (ns from {@code /proc/self/task/<tid>/schedstat}, and us from the clock ticks of {@code stat} as a check),
 * voluntary context switches (wake-ups) and bytes allocated per datagram, and the thread's tid.
 * <p>
 * {@code -Dcost.tracer='perf stat -e raw_syscalls:sys_enter -t {tid} -o /tmp/{name}.perf'} (or
 * {@code strace -c -p {tid} -o ...}) runs a tracer on the receive thread for the measured part of each step only, and
 * stops it with SIGINT ({@code {tid}}: the thread's id, {@code {name}}: the step's).
 */
public final class DatagramLinkCost {

    private static final int WARM_UP = 20_000;
    private static final int BUFFER = 4 << 20;
    /** Datagrams the tick's drain handed over (on the tick's thread, so not in the receive thread's cost). */
    private static final AtomicLong DRAINED = new AtomicLong();

    private DatagramLinkCost() {
    }

    public static void main(String[] args) throws Exception {
        List<Integer> rates = Stream.of((args.length > 0 ? args[0] : "1000,10000,50000").split(","))
                .map(Integer::valueOf).toList();
        double seconds = args.length > 1 ? Double.parseDouble(args[1]) : 3;
        int senders = args.length > 2 ? Integer.parseInt(args[2]) : 1;
        double wait = args.length > 3 ? Double.parseDouble(args[3]) : 0;
        System.out.printf("pid=%d senders=%d seconds/step=%.1f%n", ProcessHandle.current().pid(), senders, seconds);
        if (wait > 0) {
            Thread.sleep((long) (wait * 1000));
        }
        System.out.println("mode   rate   sent     received  cpu_ns/dgram  stat_us/dgram  wakeups/dgram  bytes/dgram"
                + "  tid");
        for (int rate : rates) {
            for (String mode : List.of("link", "floor")) {
                step(mode, rate, (long) (rate * seconds), senders);
            }
        }
    }

    /** The receiver under measure: its port, its count, its receive thread's Java id. */
    private interface Receiver extends AutoCloseable {
        int port();

        @Override
        void close() throws Exception;
    }

    private static void step(String mode, int rate, long count, int senders) throws Exception {
        AtomicLong received = new AtomicLong();
        AtomicLong javaId = new AtomicLong(-1);
        String name = mode + "-" + rate;
        try (Receiver receiver = mode.equals("link") ? link(name, received, javaId) : floor(name, received, javaId);
                Sender sender = new Sender(senders, receiver.port())) {
            sender.send(WARM_UP, 50_000);
            awaitCount(received, WARM_UP, 5);
            long tid = tid(name);
            Process tracer = tracer(tid, name);
            Sample before = Sample.of(tid, javaId.get());
            long got0 = received.get();
            long drained0 = DRAINED.get();
            sender.send(count, rate);
            awaitCount(received, got0 + count, 5);
            Sample after = Sample.of(tid, javaId.get());
            stop(tracer);
            long got = received.get() - got0;
            double n = Math.max(1, got - (DRAINED.get() - drained0));
            System.out.printf("%-5s %6d %8d %8d %12.0f %13.2f %14.3f %12.1f  %d%n", mode, rate, count, got,
                    (after.cpuNanos - before.cpuNanos) / n, (after.ticks - before.ticks) * 10_000.0 / n,
                    (after.wakeups - before.wakeups) / n, (after.allocated - before.allocated) / n, tid);
        }
    }

    private static Process tracer(long tid, String name) throws IOException, InterruptedException {
        String command = System.getProperty("cost.tracer");
        if (command == null) {
            return null;
        }
        command = command.replace("{tid}", Long.toString(tid)).replace("{name}", name);
        Process p = new ProcessBuilder("sh", "-c", "exec " + command).inheritIO().start();
        Thread.sleep(500); // attached
        return p;
    }

    private static void stop(Process tracer) throws IOException, InterruptedException {
        if (tracer != null) {
            new ProcessBuilder("kill", "-INT", Long.toString(tracer.pid())).inheritIO().start().waitFor();
            tracer.waitFor(10, TimeUnit.SECONDS);
        }
    }

    private static Receiver link(String name, AtomicLong received, AtomicLong javaId) throws IOException {
        DatagramLink link = DatagramLink.open("127.0.0.1", 0, BUFFER, name);
        DatagramLink.Receiver count = (data, length, from) -> {
            if (javaId.get() < 0) {
                javaId.set(Thread.currentThread().getId());
            }
            received.incrementAndGet();
        };
        link.start(count);
        ScheduledExecutorService tick = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "tick"));
        tick.scheduleAtFixedRate(() -> link.drain((data, length, from) -> {
            received.incrementAndGet();
            DRAINED.incrementAndGet();
        }), 1, 1,
                TimeUnit.SECONDS);
        return new Receiver() {
            @Override
            public int port() {
                return link.localPort();
            }

            @Override
            public void close() throws InterruptedException {
                tick.shutdownNow();
                tick.awaitTermination(5, TimeUnit.SECONDS);
                link.close();
            }
        };
    }

    private static Receiver floor(String name, AtomicLong received, AtomicLong javaId) throws IOException {
        DatagramSocket socket = new DatagramSocket(null);
        socket.setReceiveBufferSize(BUFFER);
        socket.bind(new InetSocketAddress("127.0.0.1", 0));
        ExecutorService thread = Executors.newSingleThreadExecutor(r -> new Thread(r, name));
        thread.execute(() -> {
            javaId.set(Thread.currentThread().getId());
            DatagramPacket packet = new DatagramPacket(new byte[DatagramLink.RECEIVE_BUFFER], DatagramLink.RECEIVE_BUFFER);
            try {
                while (true) {
                    socket.receive(packet);
                    received.incrementAndGet();
                }
            } catch (SocketException e) {
                // closed: the step is over
            } catch (IOException e) {
                e.printStackTrace();
            }
        });
        return new Receiver() {
            @Override
            public int port() {
                return socket.getLocalPort();
            }

            @Override
            public void close() throws InterruptedException {
                socket.close();
                thread.shutdown();
                thread.awaitTermination(5, TimeUnit.SECONDS);
            }
        };
    }

    /** Paced datagrams of 12 bytes (an AmICA frame's size) from {@code k} sockets in turn, on the caller's thread. */
    private static final class Sender implements AutoCloseable {
        private final DatagramChannel[] channels;
        private final InetSocketAddress target;
        private final ByteBuffer frame = ByteBuffer.allocateDirect(12);

        Sender(int k, int port) throws IOException {
            channels = new DatagramChannel[k];
            for (int i = 0; i < k; i++) {
                channels[i] = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
            }
            target = new InetSocketAddress("127.0.0.1", port);
        }

        void send(long count, int rate) throws IOException {
            long start = System.nanoTime();
            double interval = 1e9 / rate;
            for (long i = 0; i < count; i++) {
                long due = start + (long) (i * interval);
                long early = due - System.nanoTime();
                if (early > 0) {
                    LockSupport.parkNanos(early);
                }
                frame.clear();
                frame.putLong(0, i);
                channels[(int) (i % channels.length)].send(frame, target);
            }
        }

        @Override
        public void close() throws IOException {
            for (DatagramChannel c : channels) {
                c.close();
            }
        }
    }

    private static void awaitCount(AtomicLong received, long n, double seconds) throws InterruptedException {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (received.get() < n && System.nanoTime() < end) {
            Thread.sleep(5);
        }
    }

    /** The native id of the thread named {@code name} (a thread's comm holds its first 15 characters). */
    private static long tid(String name) throws IOException, InterruptedException {
        for (int attempt = 0; attempt < 200; attempt++) {
            try (Stream<Path> tasks = Files.list(Path.of("/proc/self/task"))) {
                for (Path t : tasks.toList()) {
                    try {
                        if (Files.readString(t.resolve("comm")).strip().equals(name)) {
                            return Long.parseLong(t.getFileName().toString());
                        }
                    } catch (IOException e) {
                        // the thread ended meanwhile
                    }
                }
            }
            Thread.sleep(10);
        }
        throw new IOException("no thread named " + name);
    }

    /** One reading of a thread's counters. */
    private record Sample(long cpuNanos, long ticks, long wakeups, long allocated) {
        static Sample of(long tid, long javaId) throws IOException {
            Path task = Path.of("/proc/self/task/" + tid);
            long cpu = Long.parseLong(Files.readString(task.resolve("schedstat")).split(" ")[0]);
            String stat = Files.readString(task.resolve("stat"));
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            long ticks = Long.parseLong(f[11]) + Long.parseLong(f[12]); // utime, stime (fields 14, 15)
            long wakeups = Files.readAllLines(task.resolve("status")).stream()
                    .filter(l -> l.startsWith("voluntary_ctxt_switches:"))
                    .mapToLong(l -> Long.parseLong(l.substring(l.indexOf(':') + 1).strip())).sum();
            long allocated = ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean())
                    .getThreadAllocatedBytes(javaId);
            return new Sample(cpu, ticks, wakeups, allocated);
        }
    }
}

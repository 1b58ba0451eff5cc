package org.tinysep.benchmarks;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.HashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.osgi.framework.launch.Framework;

/**
 * The floors, each run as its own JVM with the same options as the platform: {@code receiver <port>} counts
 * datagrams (a DatagramChannel with the radio's 4 MB receive buffer) and prints the count for every line on stdin;
 * {@code echo <port>} sends every datagram back; {@code idle} does nothing; {@code felix} starts a bare Felix
 * framework (system bundle only). Each prints {@code ready} once listening or started.
 */
public final class Bare {

    private Bare() {
    }

    public static void main(String[] args) throws Exception {
        switch (args[0]) {
            case "receiver" -> receiver(Integer.parseInt(args[1]));
            case "echo" -> echo(Integer.parseInt(args[1]));
            case "idle" -> idle();
            case "felix" -> felix(args[1]);
            case "registry" -> registry(args[1], Integer.parseInt(args[2]));
            default -> throw new IllegalArgumentException(args[0]);
        }
    }

    private static DatagramChannel open(int port) throws Exception {
        DatagramChannel ch = DatagramChannel.open();
        ch.setOption(StandardSocketOptions.SO_RCVBUF, 4 << 20);
        ch.bind(new InetSocketAddress("127.0.0.1", port));
        return ch;
    }

    private static void receiver(int port) throws Exception {
        DatagramChannel ch = open(port);
        AtomicLong count = new AtomicLong();
        Thread t = new Thread(() -> {
            ByteBuffer b = ByteBuffer.allocate(2048);
            try {
                while (true) {
                    b.clear();
                    ch.receive(b);
                    count.incrementAndGet();
                }
            } catch (Exception end) {
                // closed
            }
        }, "bare-receiver");
        t.setDaemon(true);
        t.start();
        answer(() -> Long.toString(count.get()));
    }

    private static void echo(int port) throws Exception {
        echoing(open(port));
        answer(() -> "ok");
    }

    /** Starts a daemon thread that sends every datagram back to its sender until {@code ch} is closed. */
    static void echoing(DatagramChannel ch) {
        Thread t = new Thread(() -> {
            ByteBuffer b = ByteBuffer.allocate(2048);
            try {
                while (true) {
                    b.clear();
                    SocketAddress from = ch.receive(b);
                    b.flip();
                    ch.send(b, from);
                }
            } catch (Exception end) {
                // closed
            }
        }, "bare-echo");
        t.setDaemon(true);
        t.start();
    }

    private static void idle() throws Exception {
        answer(() -> "ok");
    }

    private static void felix(String cache) throws Exception {
        HashMap<String, String> config = new HashMap<>();
        config.put("org.osgi.framework.storage", cache);
        config.put("org.osgi.framework.storage.clean", "onFirstInit");
        Framework f = new org.apache.felix.framework.FrameworkFactory().newFramework(config);
        f.start();
        answer(() -> f.getState() == org.osgi.framework.Bundle.ACTIVE ? "active" : "state " + f.getState());
        f.stop();
        f.waitForStop(10_000);
    }

    /**
     * The scale floor: a bare Felix registers {@code devices} × 2 plain services (a device's Device service
     * and one provider service, with the device's four identity properties), then unregisters them; no listener.
     * Answers "createMs stopMs".
     */
    private static void registry(String cache, int devices) throws Exception {
        HashMap<String, String> config = new HashMap<>();
        config.put("org.osgi.framework.storage", cache);
        config.put("org.osgi.framework.storage.clean", "onFirstInit");
        Framework f = new org.apache.felix.framework.FrameworkFactory().newFramework(config);
        f.start();
        org.osgi.framework.BundleContext c = f.getBundleContext();
        java.util.List<org.osgi.framework.ServiceRegistration<?>> regs = new java.util.ArrayList<>(2 * devices);
        long t0 = System.nanoTime();
        for (int i = 0; i < devices; i++) {
            java.util.Hashtable<String, Object> p = new java.util.Hashtable<>();
            p.put("tinysep.device.uid", "dev-" + i);
            p.put("tinysep.device.type", "Plain");
            p.put("tinysep.driver.uid", "drv-plain");
            p.put("tinysep.driver.name", "Plain");
            regs.add(c.registerService(Runnable.class.getName(), (Runnable) () -> { }, p));
            regs.add(c.registerService(Object.class.getName(), new Object(), p));
        }
        long t1 = System.nanoTime();
        for (org.osgi.framework.ServiceRegistration<?> r : regs) {
            r.unregister();
        }
        long t2 = System.nanoTime();
        String times = String.format(java.util.Locale.ROOT, "%.1f %.1f", (t1 - t0) / 1e6, (t2 - t1) / 1e6);
        answer(() -> times);
        f.stop();
        f.waitForStop(10_000);
    }

    /** Prints ready, then one answer per input line, until end of input. */
    private static void answer(java.util.function.Supplier<String> what) throws Exception {
        System.out.println("ready");
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in));
        while (in.readLine() != null) {
            System.out.println(what.get());
            System.out.flush();
        }
    }
}

package org.tinysep.launcher;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.time.Duration;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The web console on first use (issue 29, item 3): until someone connects to the console's port, its bundles (Jetty
 * and the console, ~10 MB resident: classes, heap, threads) stay installed and stopped while the launcher holds the
 * port. The first connection (or {@link #startNow()}, e.g. the shell's {@code tinysep:web-password}) closes the
 * launcher's socket, starts the console and waits until it serves; that first connection is then handed over to it
 * byte for byte, every later one reaches Jetty directly. Starting takes ~0.5 s on a quiet machine.
 */
final class WebOnDemand implements AutoCloseable {

    /** Starts the web console; returns once it serves, {@code false} when it did not start. */
    interface Starter {
        boolean start() throws InterruptedException;
    }

    /** How long the first connection waits for Jetty to accept it once the console has started. */
    static final Duration CONNECT_WAIT = Duration.ofSeconds(10);
    private static final Logger LOG = LoggerFactory.getLogger(WebOnDemand.class);

    private final ServerSocketChannel server;
    private final InetSocketAddress address;
    private final Starter starter;
    private final ExecutorService executor;
    private boolean started;
    private boolean served;

    private WebOnDemand(ServerSocketChannel server, InetSocketAddress address, Starter starter) {
        this.server = server;
        this.address = address;
        this.starter = starter;
        AtomicInteger n = new AtomicInteger();
        this.executor = Executors.newFixedThreadPool(2, r -> {
            Thread t = new Thread(r, "tinysep-web-on-demand-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Binds the console's address and waits for its first connection (on a thread of its own).
     *
     * @throws IOException when the address cannot be bound (another program holds the port)
     */
    static WebOnDemand listen(InetSocketAddress address, Starter starter) throws IOException {
        ServerSocketChannel server = ServerSocketChannel.open();
        try {
            server.setOption(StandardSocketOptions.SO_REUSEADDR, true); // Jetty binds the same address right after
            server.bind(address);
        } catch (IOException e) {
            server.close();
            throw e;
        }
        WebOnDemand onDemand = new WebOnDemand(server, address, starter);
        onDemand.executor.execute(onDemand::awaitFirst);
        return onDemand;
    }

    /**
     * Starts the console now, once: frees its port and starts it (later calls wait for the first to finish).
     *
     * @return whether the console serves
     */
    synchronized boolean startNow() throws InterruptedException {
        if (!started) {
            started = true;
            closeServer();
            served = starter.start();
        }
        return served;
    }

    /** @return whether the console has been started (or is starting) */
    synchronized boolean started() {
        return started;
    }

    @Override
    public void close() {
        closeServer();
        executor.shutdownNow();
    }

    private void awaitFirst() {
        SocketChannel first;
        try {
            first = server.accept();
        } catch (IOException closed) {
            return; // started another way, or the platform stops
        }
        try {
            if (startNow()) {
                handOver(first);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            LOG.debug("The web console's first connection ended: {}", e.toString());
        } finally {
            closeQuietly(first);
            executor.shutdown(); // its threads end with the first connection
        }
    }

    /** Copies the first connection to the console and its answers back until both sides are done. */
    private void handOver(SocketChannel client) throws IOException, InterruptedException {
        try (SocketChannel console = connect()) {
            Future<?> answers = executor.submit(() -> copy(console, client));
            copy(client, console);
            answers.get(CONNECT_WAIT.toSeconds(), TimeUnit.SECONDS); // the console closes once the client has
        } catch (ExecutionException | TimeoutException e) {
            LOG.debug("The web console's first connection: {}", e.toString());
        }
    }

    private SocketChannel connect() throws IOException, InterruptedException {
        long end = System.nanoTime() + CONNECT_WAIT.toNanos();
        while (true) {
            try {
                return SocketChannel.open(address);
            } catch (IOException e) {
                if (System.nanoTime() > end) {
                    throw e;
                }
                Thread.sleep(20); // Jetty restarts once when its configuration arrives
            }
        }
    }

    private static void copy(SocketChannel from, SocketChannel to) {
        ByteBuffer buffer = ByteBuffer.allocate(16 * 1024);
        try {
            while (from.read(buffer) >= 0) {
                buffer.flip();
                while (buffer.hasRemaining()) {
                    to.write(buffer);
                }
                buffer.clear();
            }
            to.shutdownOutput();
        } catch (IOException e) {
            closeQuietly(to); // one side broke off: so does the other
        }
    }

    private void closeServer() {
        closeQuietly(server);
    }

    private static void closeQuietly(java.nio.channels.Channel channel) {
        try {
            channel.close();
        } catch (IOException ignored) {
            // nothing left to do
        }
    }
}

package org.tinysep.link.udp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A UDP socket with one receive loop on its own {@link LinkThread} that {@link #close()} shuts
 * down; datagrams are handed to the receiver synchronously on the receive thread. {@link #drain} hands over every
 * datagram already waiting on the caller's thread instead (the platform tick calls it, so in lock-step every frame
 * sent before a TICK is handled before its DONE). Receive loop and drain never interleave: one lock, held while a
 * datagram is handled. Sends go out on the caller's thread: a UDP send does not wait for the peer, and a command
 * sent while the Time Controller handles a TICK is then on the wire before its DONE. A receiver that throws is
 * logged and the loop goes on.
 * <p>
 * The loop costs a datagram that arrives alone one wait (epoll) and its receive, and now and then a probe for a
 * backlog; a backlog costs one receive a datagram.
 * The socket stays non-blocking so that a drain never blocks: a blocking receive would hold the channel's read
 * lock while it waits, and the drain could neither receive nor know that nothing waits.
 * <p>
 * The AmICA UDP bus radio uses all of it; the Sun SPOT bus radio's UDP link adds its source gate in its receiver,
 * the Time Controller's synchroniser link answers each request from its receiver with {@link #send}.
 */
public final class DatagramLink implements AutoCloseable {

    /** Receives each datagram; {@code data} is reused after the call returns. */
    public interface Receiver {
        void datagram(byte[] data, int length, InetSocketAddress from);
    }

    /** Told the outcome of each send. */
    public interface SendResult {
        void done(byte[] frame, InetSocketAddress to, IOException failure);
    }

    private static final Logger LOG = LoggerFactory.getLogger(DatagramLink.class);
    /** Larger than any valid frame, so an oversize datagram is seen as such rather than cut silently. */
    static final int RECEIVE_BUFFER = 2048;
    /** While no backlog is found, the receive loop probes for one after every 16th wake-up at most. */
    static final int MAX_PROBE_INTERVAL = 16;

    private final DatagramChannel channel;
    private final Selector selector;
    private final LinkThread receiveThread;
    private final ByteBuffer buffer = ByteBuffer.allocate(RECEIVE_BUFFER);
    private final Consumer<SelectionKey> ignoreKey = key -> { };
    private volatile boolean open = true;
    // counted by the receive loop only, read by the cost tests
    private volatile long loopWaits;
    private volatile long loopEmptyReceives;
    private volatile long loopDatagrams;

    private DatagramLink(DatagramChannel channel, Selector selector, String threadName) {
        this.channel = channel;
        this.selector = selector;
        this.receiveThread = new LinkThread(threadName);
    }

    /**
     * Binds the socket; nothing is received until {@link #start(Receiver)}.
     *
     * @param receiveBufferBytes the socket's receive buffer (SO_RCVBUF); 0 keeps the system's default
     * @param threadName         the name of the receive thread
     * @throws IOException if the address cannot be bound, e.g. the port is taken ({@link java.net.BindException})
     */
    public static DatagramLink open(String bindAddress, int port, int receiveBufferBytes, String threadName)
            throws IOException {
        DatagramChannel channel = DatagramChannel.open();
        Selector selector = null;
        try {
            if (receiveBufferBytes > 0) {
                channel.setOption(StandardSocketOptions.SO_RCVBUF, receiveBufferBytes);
            }
            channel.bind(new InetSocketAddress(InetAddress.getByName(bindAddress), port));
            channel.configureBlocking(false);
            selector = Selector.open();
            channel.register(selector, SelectionKey.OP_READ);
        } catch (IOException | RuntimeException e) {
            channel.close();
            if (selector != null) {
                selector.close();
            }
            throw e;
        }
        return new DatagramLink(channel, selector, threadName);
    }

    /** Starts the receive loop; datagrams queued in the socket buffer meanwhile are not lost. */
    public void start(Receiver receiver) {
        receiveThread.execute(() -> receiveLoop(receiver));
    }

    public int localPort() {
        return local().getPort();
    }

    public String localAddress() {
        InetSocketAddress a = local();
        return a.getAddress().getHostAddress() + ":" + a.getPort();
    }

    private InetSocketAddress local() {
        try {
            return (InetSocketAddress) channel.getLocalAddress();
        } catch (IOException e) {
            return new InetSocketAddress(0);
        }
    }

    public int receiveBufferSize() {
        try {
            return channel.getOption(StandardSocketOptions.SO_RCVBUF);
        } catch (IOException e) {
            return -1;
        }
    }

    /**
     * Waits until the socket is readable and receives one datagram. Only when a backlog has formed (a receive after
     * the first datagram of a wake-up found another one) does it receive on without waiting, until the socket is
     * empty; a datagram that arrives alone so costs one wait and its receive, not a third call that finds nothing.
     * The backlog is probed for after every wake-up while one is found, then after every 2nd, 4th .. 16th.
     */
    private void receiveLoop(Receiver receiver) {
        int probeEvery = 1;
        int sinceProbe = 0;
        while (open) {
            if (!awaitReadable()) {
                return;
            }
            if (!receiveOne(receiver, true) || ++sinceProbe < probeEvery) {
                continue;
            }
            sinceProbe = 0;
            int backlog = 0;
            while (open && receiveOne(receiver, true)) {
                backlog++;
            }
            probeEvery = backlog > 0 ? 1 : Math.min(2 * probeEvery, MAX_PROBE_INTERVAL);
        }
    }

    /** @return false once the selector is closed */
    private boolean awaitReadable() {
        try {
            selector.select(ignoreKey); // no selected-key set: nothing allocated per wake-up
            loopWaits++;
        } catch (ClosedSelectorException e) {
            return false;
        } catch (IOException e) {
            if (open) {
                LOG.warn("UDP receive on {} failed, continuing: {}", localAddress(), e.toString());
            }
        }
        return true;
    }

    /** The receive loop's waits for the socket (each a system call and, when it blocks, a wake-up). */
    long loopWaits() {
        return loopWaits;
    }

    /** The receive loop's receives that found nothing (a system call for nothing). */
    long loopEmptyReceives() {
        return loopEmptyReceives;
    }

    /** The datagrams the receive loop handed over (those of {@link #drain} not counted). */
    long loopDatagrams() {
        return loopDatagrams;
    }

    /**
     * Hands every datagram already waiting in the socket to {@code receiver}, on the caller's thread, and returns
     * when none is left. Waits for a datagram the receive loop is handling at the moment.
     *
     * @return how many datagrams it handed over
     */
    public int drain(Receiver receiver) {
        int n = 0;
        synchronized (buffer) {
            while (open && receiveOne(receiver, false)) {
                n++;
            }
        }
        return n;
    }

    /** Receives one datagram if one waits and hands it over, both under one lock; @return whether it did */
    private boolean receiveOne(Receiver receiver, boolean loop) {
        synchronized (buffer) {
            buffer.clear();
            SocketAddress from;
            try {
                from = channel.receive(buffer);
            } catch (IOException e) {
                if (open) {
                    LOG.warn("UDP receive on {} failed, continuing: {}", localAddress(), e.toString());
                }
                return false;
            }
            if (from == null) {
                if (loop) {
                    loopEmptyReceives++;
                }
                return false;
            }
            if (loop) {
                loopDatagrams++;
            }
            try {
                receiver.datagram(buffer.array(), buffer.position(), (InetSocketAddress) from);
            } catch (RuntimeException e) {
                LOG.error("Datagram handling on {} failed; the receive loop goes on", localAddress(), e);
            }
            return true;
        }
    }

    /** Sends a datagram on the caller's thread and reports the outcome; a closed transport fails at once. */
    public void send(byte[] frame, InetSocketAddress to, SendResult result) {
        if (!open) {
            result.done(frame, to, new IOException("bus radio is closed"));
            return;
        }
        IOException failure = null;
        try {
            if (channel.send(ByteBuffer.wrap(frame), to) == 0) {
                failure = new IOException("the socket's send buffer is full; datagram dropped");
            }
        } catch (IOException e) {
            failure = e;
        }
        result.done(frame, to, failure);
    }

    @Override
    public void close() {
        open = false;
        try {
            selector.close();
            channel.close();
        } catch (IOException e) {
            LOG.debug("closing {}: {}", localAddress(), e.toString());
        }
        receiveThread.close();
    }
}

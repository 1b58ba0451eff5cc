package org.tinysep.amica.busradio.udp.internal;

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
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The UDP socket of the driver: one receive loop on its own single-thread executor that {@link #close()} shuts
 * down; datagrams are handed to the receiver synchronously on the receive thread. {@link #drain} hands over every
 * datagram already waiting on the caller's thread instead (the platform tick calls it, so in lock-step every frame
 * sent before a TICK is handled before its DONE). Receive loop and drain never interleave: one lock, held while a
 * datagram is handled. Sends go out on the caller's thread: a UDP send does not wait for the peer, and a command
 * sent while the Time Controller handles a TICK is then on the wire before its DONE.
 */
final class UdpTransport implements AutoCloseable {

    /** Receives each datagram; {@code data} is reused after the call returns. */
    interface Receiver {
        void datagram(byte[] data, int length, InetSocketAddress from);
    }

    /** Told the outcome of each send. */
    interface SendResult {
        void done(byte[] frame, InetSocketAddress to, IOException failure);
    }

    private static final Logger LOG = LoggerFactory.getLogger(UdpTransport.class);
    /** Larger than any valid frame, so an oversize datagram is seen as such rather than cut silently. */
    static final int RECEIVE_BUFFER = 2048;

    private final DatagramChannel channel;
    private final Selector selector;
    private final ExecutorService receiveExecutor;
    private final ByteBuffer buffer = ByteBuffer.allocate(RECEIVE_BUFFER);
    private volatile boolean open = true;

    private UdpTransport(DatagramChannel channel, Selector selector, String name) {
        this.channel = channel;
        this.selector = selector;
        this.receiveExecutor = Executors.newSingleThreadExecutor(r -> new Thread(r, name + "-receive"));
    }

    /** Binds the socket; nothing is received until {@link #start(Receiver)}. */
    static UdpTransport open(String bindAddress, int port, int receiveBufferBytes, String name) throws IOException {
        DatagramChannel channel = DatagramChannel.open();
        Selector selector = null;
        try {
            channel.setOption(StandardSocketOptions.SO_RCVBUF, receiveBufferBytes);
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
        return new UdpTransport(channel, selector, name);
    }

    /** Starts the receive loop; datagrams queued in the socket buffer meanwhile are not lost. */
    void start(Receiver receiver) {
        receiveExecutor.execute(() -> receiveLoop(receiver));
    }

    int localPort() {
        return local().getPort();
    }

    String localAddress() {
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

    int receiveBufferSize() {
        try {
            return channel.getOption(StandardSocketOptions.SO_RCVBUF);
        } catch (IOException e) {
            return -1;
        }
    }

    private void receiveLoop(Receiver receiver) {
        while (open) {
            try {
                selector.select();
                selector.selectedKeys().clear();
            } catch (ClosedSelectorException e) {
                return;
            } catch (IOException e) {
                if (open) {
                    LOG.warn("UDP receive on {} failed, continuing: {}", localAddress(), e.toString());
                }
                continue;
            }
            drain(receiver);
        }
    }

    /**
     * Hands every datagram already waiting in the socket to {@code receiver}, on the caller's thread, and returns
     * when none is left. Waits for a datagram the receive loop is handling at the moment.
     *
     * @return how many datagrams it handed over
     */
    int drain(Receiver receiver) {
        int n = 0;
        synchronized (buffer) {
            while (open) {
                buffer.clear();
                SocketAddress from;
                try {
                    from = channel.receive(buffer);
                } catch (IOException e) {
                    if (open) {
                        LOG.warn("UDP receive on {} failed, continuing: {}", localAddress(), e.toString());
                    }
                    return n;
                }
                if (from == null) {
                    return n;
                }
                n++;
                try {
                    receiver.datagram(buffer.array(), buffer.position(), (InetSocketAddress) from);
                } catch (RuntimeException e) {
                    LOG.error("Datagram handling failed; the receive loop goes on", e);
                }
            }
        }
        return n;
    }

    /** Sends a datagram on the caller's thread and reports the outcome; a closed transport fails at once. */
    void send(byte[] frame, InetSocketAddress to, SendResult result) {
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
        receiveExecutor.shutdown();
        try {
            if (!receiveExecutor.awaitTermination(2, TimeUnit.SECONDS)) {
                receiveExecutor.shutdownNow();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

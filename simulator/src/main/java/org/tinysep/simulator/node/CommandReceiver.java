package org.tinysep.simulator.node;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;

/**
 * Receives the frames the platform sends to any AmICA node and hands them to that node: on the simulation's thread
 * at the start of every virtual second ({@link #drainNow}), and in real time also on its own thread as they arrive.
 * In lock-step only the simulation's thread carries them out, so a command's answer always goes out at the start of
 * the virtual second after the one in which the platform sent the command, never at a moment the scheduler picks.
 */
final class CommandReceiver implements AutoCloseable {

    private final Selector selector;
    private final List<AmicaNode> nodes;
    private final ByteBuffer buf = ByteBuffer.allocate(AmicaCodec.MAX_FRAME + 1);
    private final ExecutorService executor = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "amica-commands");
        t.setDaemon(true);
        return t;
    });

    /** @param ownThread also carry out commands as they arrive (real time); lock-step passes false */
    CommandReceiver(List<AmicaNode> nodes, boolean ownThread) throws IOException {
        this.nodes = List.copyOf(nodes);
        selector = Selector.open();
        for (AmicaNode n : nodes) {
            n.port().channel().configureBlocking(false);
            n.port().channel().register(selector, SelectionKey.OP_READ, n);
        }
        if (ownThread) {
            executor.execute(this::loop);
        }
    }

    private void loop() {
        try {
            while (selector.isOpen()) {
                selector.select();
                for (SelectionKey key : selector.selectedKeys()) {
                    if (key.isValid()) {
                        drain((AmicaNode) key.attachment());
                    }
                }
                selector.selectedKeys().clear();
            }
        } catch (IOException | ClosedSelectorException e) {
            // closed: the simulation ends
        }
    }

    /**
     * Carries out every command already waiting for any node, on the caller's thread. The simulation calls it at the
     * start of each virtual second, so in lock-step a command the platform sent before its DONE is carried out
     * before the node's next status report, however late this class's own thread gets the CPU.
     *
     * @return how many of the answers report a changed value (the lock-step paces them like any change)
     */
    int drainNow() {
        int changed = 0;
        for (AmicaNode node : nodes) {
            try {
                changed += drain(node);
            } catch (IOException e) {
                return changed; // closed: the simulation ends
            }
        }
        return changed;
    }

    /** One node's waiting commands, in order; one lock so that the thread and {@link #drainNow} never interleave. */
    private synchronized int drain(AmicaNode node) throws IOException {
        int changed = 0;
        buf.clear();
        while (node.port().channel().isOpen() && node.port().channel().receive(buf) != null) {
            changed += handle(node, buf.array(), buf.position());
            buf.clear();
        }
        return changed;
    }

    private static int handle(AmicaNode node, byte[] b, int length) {
        try {
            AmicaFrame f = AmicaCodec.decode(b, 0, length);
            if (!f.receiver().equals(node.port().address())) {
                NodeLog.LOG.warning("node " + node.port().address() + " got a frame for " + f.receiver());
                return 0;
            }
            return node.command(AmicaPayloads.decode(f.payload()));
        } catch (AmicaProtocolException e) {
            NodeLog.LOG.warning("node " + node.port().address() + " dropped a bad frame: " + e.getMessage());
            return 0;
        }
    }

    @Override
    public void close() throws IOException {
        selector.close();
        executor.shutdownNow();
        try {
            executor.awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

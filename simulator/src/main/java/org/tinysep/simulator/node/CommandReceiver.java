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

/** One thread that receives the frames the platform sends to any AmICA node and hands them to that node. */
final class CommandReceiver implements AutoCloseable {

    private final Selector selector;
    private final ExecutorService executor = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "amica-commands");
        t.setDaemon(true);
        return t;
    });

    CommandReceiver(List<AmicaNode> nodes) throws IOException {
        selector = Selector.open();
        for (AmicaNode n : nodes) {
            n.port().channel().configureBlocking(false);
            n.port().channel().register(selector, SelectionKey.OP_READ, n);
        }
        executor.execute(this::loop);
    }

    private void loop() {
        ByteBuffer buf = ByteBuffer.allocate(AmicaCodec.MAX_FRAME + 1);
        try {
            while (selector.isOpen()) {
                selector.select();
                for (SelectionKey key : selector.selectedKeys()) {
                    AmicaNode node = (AmicaNode) key.attachment();
                    buf.clear();
                    while (key.isValid() && ((java.nio.channels.DatagramChannel) key.channel()).receive(buf) != null) {
                        handle(node, buf.array(), buf.position());
                        buf.clear();
                    }
                }
                selector.selectedKeys().clear();
            }
        } catch (IOException | ClosedSelectorException e) {
            // closed: the simulation ends
        }
    }

    private static void handle(AmicaNode node, byte[] b, int length) {
        try {
            AmicaFrame f = AmicaCodec.decode(b, 0, length);
            if (!f.receiver().equals(node.port().address())) {
                NodeLog.LOG.warning("node " + node.port().address() + " got a frame for " + f.receiver());
                return;
            }
            node.command(AmicaPayloads.decode(f.payload()));
        } catch (AmicaProtocolException e) {
            NodeLog.LOG.warning("node " + node.port().address() + " dropped a bad frame: " + e.getMessage());
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

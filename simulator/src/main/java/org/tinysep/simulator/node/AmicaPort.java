package org.tinysep.simulator.node;

import java.io.IOException;
import java.nio.channels.DatagramChannel;
import java.util.concurrent.atomic.AtomicInteger;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;

/**
 * One AmICA node's own UDP socket ({@link RadioSocket}): frames to the bus radio (sequence numbers 0..255), commands
 * back from it.
 */
final class AmicaPort implements AutoCloseable {

    /** The battery and vendor every simulated AmICA node reports in its keep-alive. */
    private static final int BATTERY_MV = 3000;
    private static final int VENDOR = 0x0A11;

    private final AmicaAddress address;
    private final RadioSocket socket;
    private final AtomicInteger sequence = new AtomicInteger();

    AmicaPort(AmicaAddress address, Target target) throws IOException {
        this.address = address;
        this.socket = new RadioSocket(target, target.amica());
    }

    AmicaAddress address() {
        return address;
    }

    DatagramChannel channel() {
        return socket.channel();
    }

    /** Sends this node's keep-alive: {@code uptime} seconds since start-up, its product id and serial number. */
    void sendKeepAlive(long uptime, int productId, long serial) {
        send(new KeepAlive(uptime, BATTERY_MV, VENDOR, productId, serial));
    }

    void send(AmicaPayload payload) {
        socket.send(AmicaCodec.encode(AmicaFrame.toPlatform(address, sequence.getAndIncrement() & 0xFF,
                AmicaPayloads.encode(payload))), "node " + address);
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}

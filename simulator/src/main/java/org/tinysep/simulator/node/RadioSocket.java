package org.tinysep.simulator.node;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;

/**
 * A simulated node's UDP socket towards one bus radio, for both node families: bound where the
 * {@link Target} says, it sends encoded frames to the radio; a send that fails is logged, never thrown (a real node
 * does not stop when nobody listens).
 */
final class RadioSocket implements AutoCloseable {

    private final DatagramChannel channel;
    private final InetSocketAddress radio;

    /** @param radio the bus radio's address, e.g. {@code target.amica()} */
    RadioSocket(Target target, InetSocketAddress radio) throws IOException {
        this.radio = radio;
        this.channel = DatagramChannel.open().bind(target.bind());
    }

    /** @return the socket, e.g. to receive the radio's commands on it */
    DatagramChannel channel() {
        return channel;
    }

    /** @param sender who sends, for the log line, e.g. {@code node 1.2} or {@code Sun SPOT 0014.4F01.0000.1234} */
    void send(byte[] frame, String sender) {
        try {
            channel.send(ByteBuffer.wrap(frame), radio);
        } catch (IOException e) {
            NodeLog.LOG.warning(sender + " could not send to " + radio + ": " + e.getMessage());
        }
    }

    @Override
    public void close() throws IOException {
        channel.close();
    }
}

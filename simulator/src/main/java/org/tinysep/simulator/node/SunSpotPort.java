package org.tinysep.simulator.node;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/** The UDP socket all Sun SPOT nodes share (the source address is in the frame; Sun SPOTs take no commands). */
final class SunSpotPort implements AutoCloseable {

    private final DatagramChannel channel;
    private final InetSocketAddress radio;

    SunSpotPort(Target target) throws IOException {
        this.radio = target.sunSpot();
        this.channel = DatagramChannel.open().bind(target.bind());
    }

    void send(SunSpotAddress source, SunSpotPayload payload) {
        byte[] b = SunSpotCodec.encode(SunSpotFrame.of(source, SunSpotPayloads.encode(payload)));
        try {
            channel.send(ByteBuffer.wrap(b), radio);
        } catch (IOException e) {
            NodeLog.LOG.warning("Sun SPOT " + source + " could not send to " + radio + ": " + e.getMessage());
        }
    }

    @Override
    public void close() throws IOException {
        channel.close();
    }
}

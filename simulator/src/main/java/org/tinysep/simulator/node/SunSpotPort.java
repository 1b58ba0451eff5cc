package org.tinysep.simulator.node;

import java.io.IOException;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/**
 * The UDP socket ({@link RadioSocket}) all Sun SPOT nodes share: the source address is in the frame, and Sun SPOTs
 * take no commands.
 */
final class SunSpotPort implements AutoCloseable {

    private final RadioSocket socket;

    SunSpotPort(Target target) throws IOException {
        this.socket = new RadioSocket(target, target.sunSpot());
    }

    void send(SunSpotAddress source, SunSpotPayload payload) {
        byte[] frame = SunSpotCodec.encode(SunSpotFrame.of(source, SunSpotPayloads.encode(payload)));
        socket.send(frame, "Sun SPOT " + source);
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}

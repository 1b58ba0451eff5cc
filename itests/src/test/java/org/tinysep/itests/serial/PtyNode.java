package org.tinysep.itests.serial;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.testsupport.serial.PtyPeer;

/**
 * A simulated AmICA node behind the modified base node: writes real frames into the node's end of a
 * pseudo-terminal pair (the serial counterpart of {@code org.tinysep.itests.AmicaNode}) and reads what the
 * platform sends back.
 */
final class PtyNode implements AutoCloseable {

    private final PtyPeer peer;
    private final int netgroup;
    private final int address;
    private final List<AmicaNodeType> types;
    private int sequence;

    PtyNode(Path end, int netgroup, int address, AmicaNodeType... types) throws IOException {
        this.peer = new PtyPeer(end);
        this.netgroup = netgroup;
        this.address = address;
        this.types = List.of(types);
    }

    void keepAlive() throws IOException {
        send(new KeepAlive(120, 2900, 1, AmicaNodeType.productId(types), 4242));
    }

    void motion(boolean detected) throws IOException {
        send(new MotionDetection(detected));
    }

    void send(AmicaPayload payload) throws IOException {
        raw(frame(payload));
    }

    /** @return the bytes of the node's next frame with this payload (its sequence number advances) */
    byte[] frame(AmicaPayload payload) {
        return AmicaCodec.encode(new AmicaFrame(netgroup, address, 0, sequence++ & 0xFF,
                AmicaPayloads.encode(payload)));
    }

    /** Writes any bytes, e.g. line noise, frames and noise concatenated. */
    void raw(byte[]... parts) throws IOException {
        for (byte[] p : parts) {
            peer.write(p);
        }
    }

    /** @return the next frame of {@code payloadLength} payload bytes the platform sends to this node (5 s) */
    AmicaFrame receive(int payloadLength) throws Exception {
        byte[] bytes = peer.read(AmicaCodec.HEADER_LENGTH + payloadLength);
        return AmicaCodec.decode(bytes, 0, bytes.length);
    }

    @Override
    public void close() throws IOException {
        peer.close();
    }
}

package org.tinysep.sunspot.busradio.internal;

import java.time.Instant;
import org.tinysep.api.log.Direction;
import org.tinysep.device.support.intake.PacketIntake;
import org.tinysep.device.support.intake.RejectCounter;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.sunspot.protocol.RejectReason;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * The one decoder path every link feeds: turns a packet into a delivery to a bus device (created on the node's
 * first valid packet of any kind, thesis 4.4.1.3) or a counted rejection. Every packet ends up in the packet log, a
 * rejected one with its reason. Counting, copying and decoding a datagram ({@code from} is the link and remote end,
 * e.g. {@code udp 127.0.0.1:5000}), refused sources and the sampled packet log are the shared
 * {@link PacketIntake}'s. Thread-safe: each link calls it on its own receive thread.
 */
final class PacketHandler extends PacketIntake<SunSpotFrame, RejectReason, SunSpotProtocolException, String> {

    /** A datagram is one frame; the reason of a bad one is its exception's (a lambda: see the AmICA FrameHandler). */
    private static final Codec<SunSpotFrame, RejectReason, SunSpotProtocolException> CODEC = new Codec<>(
            raw -> SunSpotCodec.decode(raw, 0, raw.length), SunSpotProtocolException.class, e -> e.reason());

    private final SunSpotNodes nodes;

    PacketHandler(DriverContext context, SunSpotNodes nodes, RejectCounter<RejectReason> rejects) {
        super(context, CODEC, rejects::reject);
        this.nodes = nodes;
    }

    @Override
    protected void handle(SunSpotFrame frame, byte[] raw, String from, Instant stamp) {
        Instant at = stamp == null ? context().now() : stamp;
        SunSpotSensorType type;
        try {
            byte[] payload = frame.payload();
            if (payload.length == 0 || (payload[0] & 0xFF) != frame.sensorType()) {
                throw new SunSpotProtocolException(RejectReason.TYPE_MISMATCH,
                        "sensor type " + frame.sensorType() + " does not start the payload");
            }
            SunSpotPayloads.decode(payload); // checks it; the bus device forwards the bytes unanalysed
            type = SunSpotSensorType.fromCode(frame.sensorType()).orElseThrow(() -> new SunSpotProtocolException(
                    RejectReason.UNKNOWN_PAYLOAD, "sensor type " + frame.sensorType()));
        } catch (SunSpotProtocolException e) {
            reject(e.reason(), e.getMessage(), raw, from);
            return;
        }
        SunSpotBusDevice device = nodes.findOrCreate(frame.source(), type, from);
        if (device == null) { // over the node cap: counted by the node table
            sample(from, raw, "rejected: Sun SPOT " + frame.source() + " would exceed maxNodes");
            return;
        }
        context().reporter().packet(Direction.RECEIVED, "node " + frame.source() + " via " + from, raw, "");
        device.received(frame, type, from, at);
    }

    @Override
    protected String origin(String from) {
        return from;
    }

    /** A platform tick: silent nodes go OFFLINE; the summary of rejected input not kept, at most once a minute. */
    void tick(Instant now) {
        nodes.checkHealth(now);
        flushRejects();
    }
}

package org.tinysep.sunspot.busradio.internal;

import java.time.Instant;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.log.Direction;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.RejectSampler;
import org.tinysep.sunspot.protocol.RejectReason;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * The one decoder path every link feeds: turns a packet into a delivery to a bus device (created on the node's
 * first valid packet of any kind, thesis 4.4.1.3) or a counted rejection. Every packet ends up in the packet log, a
 * rejected one with its reason. Thread-safe: each link calls it on its own receive thread.
 */
final class PacketHandler {

    private final DriverContext context;
    private final SunSpotNodes nodes;
    private final RejectCounter rejects;
    private final RejectSampler sampler;
    private final AtomicLong received = new AtomicLong();

    PacketHandler(DriverContext context, SunSpotNodes nodes, RejectCounter rejects) {
        this.context = context;
        this.nodes = nodes;
        this.rejects = rejects;
        this.sampler = new RejectSampler(context.reporter(), context.driverUid());
    }

    /**
     * Handles bytes that must be exactly one frame, such as a UDP datagram; {@code data} may be reused after.
     *
     * @param from the link and remote end, e.g. {@code udp 127.0.0.1:5000}
     */
    void datagram(byte[] data, int length, String from) {
        received.incrementAndGet();
        byte[] raw = Arrays.copyOf(data, length);
        SunSpotFrame frame;
        try {
            frame = SunSpotCodec.decode(raw, 0, length);
        } catch (SunSpotProtocolException e) {
            reject(e.reason(), e.getMessage(), raw, from);
            return;
        }
        handle(frame, raw, from);
    }

    /**
     * Handles a frame whose framing was checked already: found in a byte stream, or built from an SDK radiogram.
     *
     * @param raw the bytes as they arrived, for the packet log (a radiogram's payload, a stream frame's bytes)
     */
    void frame(SunSpotFrame frame, byte[] raw, String from) {
        received.incrementAndGet();
        handle(frame, raw, from);
    }

    /**
     * Records input that a link's framing rejected, e.g. a run of bytes the stream decoder skipped: counted under
     * its reason and written to the packet log.
     */
    void rejected(RejectReason reason, String message, byte[] raw, String from) {
        reject(reason, message, raw, from);
    }

    /** Handles a packet a link refused before it became a frame, e.g. an empty radiogram: counted and rejected. */
    void refused(SunSpotProtocolException e, byte[] raw, String from) {
        received.incrementAndGet();
        reject(e.reason(), e.getMessage(), raw, from);
    }

    private void handle(SunSpotFrame frame, byte[] raw, String from) {
        Instant at = context.now();
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
            sampler.rejected(from, raw, "rejected: Sun SPOT " + frame.source() + " would exceed maxNodes");
            return;
        }
        context.reporter().packet(Direction.RECEIVED, "node " + frame.source() + " via " + from, raw, "");
        device.received(frame, type, from, at);
    }

    private void reject(RejectReason reason, String message, byte[] raw, String from) {
        rejects.reject(reason, message, from);
        sampler.rejected(from, raw, message);
    }

    /** Records a datagram a link refused for its source (the link's {@code SourceGate} counted it), sampled. */
    void refusedSource(String why, byte[] data, int length, String from) {
        received.incrementAndGet();
        sampler.rejected(from, Arrays.copyOf(data, length), why);
    }

    /** A platform tick: silent nodes go OFFLINE; the summary of rejected input not kept, at most once a minute. */
    void tick(Instant now) {
        nodes.checkHealth(now);
        sampler.flush();
    }

    /** @return how many packets (datagrams, stream frames, radiograms) were handed in, rejected ones included */
    long received() {
        return received.get();
    }
}

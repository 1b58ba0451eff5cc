package org.tinysep.sunspot.busradio.internal;

import java.util.Optional;
import java.util.regex.Pattern;
import org.osgi.service.component.annotations.Component;
import org.tinysep.api.packet.PacketDescriber;
import org.tinysep.device.support.intake.FrameWords;
import org.tinysep.sunspot.protocol.BurstChunk;
import org.tinysep.sunspot.protocol.ButtonReport;
import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/**
 * Sun SPOT frames in words for the packet log's readers (the web console), as a whiteboard service. Asked first for
 * this bus radio's origins ({@code node 0014.4F01.0000.A001 via …}, the bus device's {@code SunSpot…} names).
 */
@Component(service = PacketDescriber.class)
public final class SunSpotPacketDescriber implements PacketDescriber {

    private static final Pattern NODE_ORIGIN = Pattern.compile("(?i).*node [0-9a-f]{4}\\..*");

    @Override
    public String protocol() {
        return "Sun SPOT";
    }

    @Override
    public boolean usualFor(String origin) {
        return origin.contains("SunSpot") || NODE_ORIGIN.matcher(origin).matches();
    }

    @Override
    public Optional<String> describe(byte[] bytes) {
        return FrameWords.<SunSpotFrame, SunSpotPayload, SunSpotProtocolException>of(bytes,
                b -> SunSpotCodec.decode(b, 0, b.length), f -> "Sun SPOT " + f.source() + ": ",
                f -> SunSpotPayloads.decode(f.payload()), SunSpotPacketDescriber::payload);
    }

    private static String payload(SunSpotPayload p) {
        if (p instanceof MovementDetection m) {
            String at = m.position() == null ? "" : " at (" + m.position().xCentimetres() + ", "
                    + m.position().yCentimetres() + ", " + m.position().zCentimetres() + ") cm";
            return (m.detected() ? "movement detected" : "no movement") + at;
        }
        if (p instanceof TemperatureStatus t) {
            return "temperature " + t.celsius() + " °C";
        }
        if (p instanceof LightStatus l) {
            return "light " + l.percent() + " %";
        }
        if (p instanceof PetMovementDetection pm) {
            return pm.detected() ? "pet movement detected" : "no pet movement";
        }
        if (p instanceof ButtonReport b) {
            return "switch " + b.button() + (b.pressed() ? " pressed" : " released");
        }
        if (p instanceof MovementSummaryReport s) {
            return "movement summary over " + s.spanMillis() + " ms: mean (" + s.mean().xMg() + ", " + s.mean().yMg()
                    + ", " + s.mean().zMg() + ") mg, spread " + s.magnitudeSdMg() + " mg, peak " + s.peakMg() + " mg";
        }
        if (p instanceof BurstChunk c) {
            return "acceleration burst " + c.burstId() + ", chunk " + (c.chunkIndex() + 1) + " of " + c.chunkCount()
                    + ": " + c.samples().size() + " samples at " + c.sampleRateHz() + " Hz";
        }
        return String.valueOf(p);
    }
}

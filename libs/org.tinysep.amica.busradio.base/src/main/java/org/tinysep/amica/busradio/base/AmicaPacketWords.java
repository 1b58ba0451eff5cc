package org.tinysep.amica.busradio.base;

import java.util.Optional;
import org.tinysep.amica.protocol.AmicaCodec;
import org.tinysep.amica.protocol.AmicaFrame;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.amica.protocol.SpeakerControl;
import org.tinysep.api.packet.PacketDescriber;
import org.tinysep.device.support.intake.FrameWords;

/**
 * AmICA frames in words for the packet log's readers. Each AmICA bus radio bundle registers it as a
 * {@link PacketDescriber} (a DS component subclass of its own: bnd writes components only for the bundle's own
 * classes).
 */
public class AmicaPacketWords implements PacketDescriber {

    @Override
    public final String protocol() {
        return "AmICA";
    }

    @Override
    public final Optional<String> describe(byte[] bytes) {
        return FrameWords.<AmicaFrame, AmicaPayload, AmicaProtocolException>of(bytes,
                b -> AmicaCodec.decode(b, 0, b.length),
                f -> "AmICA " + f.sender() + " → " + f.receiver() + " #" + f.sequence() + ": ",
                f -> AmicaPayloads.decode(f.payload()), AmicaPacketWords::payload);
    }

    private static String payload(AmicaPayload p) {
        if (p instanceof KeepAlive k) {
            return "keep-alive, " + k.nodeTypes() + ", battery " + k.batteryMillivolts() + " mV, up "
                    + k.uptimeSeconds() + " s, serial " + k.serialNumber();
        }
        if (p instanceof MotionDetection m) {
            return m.detected() ? "motion detected" : "no motion";
        }
        if (p instanceof ReedSwitchStatus r) {
            return r.open() ? "reed switch open" : "reed switch closed";
        }
        if (p instanceof LightControl l) {
            return "light " + l.percent() + " %";
        }
        if (p instanceof SpeakerControl s) {
            return "speaker volume " + s.percent() + " %";
        }
        if (p instanceof HeaterControl h) {
            return "heater " + h.percent() + " %";
        }
        return String.valueOf(p);
    }
}

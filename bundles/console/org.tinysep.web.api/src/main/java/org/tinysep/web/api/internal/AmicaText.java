package org.tinysep.web.api.internal;

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

/**
 * An AmICA frame in words (only loaded once {@link PacketDecoder} found the protocol library); the decoding and its
 * fallbacks are {@link FrameText}'s.
 */
final class AmicaText {

    private AmicaText() {
    }

    static String of(byte[] bytes) {
        return FrameText.<AmicaFrame, AmicaPayload, AmicaProtocolException>of(bytes,
                b -> AmicaCodec.decode(b, 0, b.length),
                f -> "AmICA " + f.sender() + " → " + f.receiver() + " #" + f.sequence() + ": ",
                f -> AmicaPayloads.decode(f.payload()), AmicaText::payload);
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

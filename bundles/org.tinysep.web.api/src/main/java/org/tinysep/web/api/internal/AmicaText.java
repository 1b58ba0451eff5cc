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

/** An AmICA frame in words (only loaded once {@link PacketDecoder} found the protocol library). */
final class AmicaText {

    private AmicaText() {
    }

    static String of(byte[] bytes) {
        AmicaFrame f;
        try {
            f = AmicaCodec.decode(bytes, 0, bytes.length);
        } catch (AmicaProtocolException e) {
            return "";
        }
        String head = "AmICA " + f.sender() + " → " + f.receiver() + " #" + f.sequence() + ": ";
        try {
            return head + payload(AmicaPayloads.decode(f.payload()));
        } catch (AmicaProtocolException e) {
            return head + "payload not understood (" + e.getMessage() + ")";
        }
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

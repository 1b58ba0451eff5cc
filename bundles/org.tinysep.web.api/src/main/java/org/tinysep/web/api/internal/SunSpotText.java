package org.tinysep.web.api.internal;

import org.tinysep.sunspot.protocol.LightStatus;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.TemperatureStatus;

/** A Sun SPOT frame in words (only loaded once {@link PacketDecoder} found the protocol library). */
final class SunSpotText {

    private SunSpotText() {
    }

    static String of(byte[] bytes) {
        SunSpotFrame f;
        try {
            f = SunSpotCodec.decode(bytes, 0, bytes.length);
        } catch (SunSpotProtocolException e) {
            return "";
        }
        String head = "Sun SPOT " + f.source() + ": ";
        try {
            return head + payload(SunSpotPayloads.decode(f.payload()));
        } catch (SunSpotProtocolException e) {
            return head + "payload not understood (" + e.getMessage() + ")";
        }
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
        return String.valueOf(p);
    }
}

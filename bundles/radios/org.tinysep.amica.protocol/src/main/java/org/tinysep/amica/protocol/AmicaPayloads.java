package org.tinysep.amica.protocol;

import java.util.Objects;
import org.tinysep.link.frame.PayloadRules;

/**
 * Converts between payload bytes (thesis Table 3.1) and {@link AmicaPayload} records. The payload type is named by
 * its first two bytes; lengths are exact (16 for a keep-alive, 4 for the others), the third byte of a 4-byte payload
 * must be 0 and its value byte must be in range. Multi-byte numbers are big-endian. Stateless and thread-safe.
 * <p>
 * The rules and number formats are shared with the Sun SPOT protocol ({@code org.tinysep.link.frame.PayloadRules});
 * this class keeps the AmICA payload table.
 */
public final class AmicaPayloads {

    private static final PayloadRules<RejectReason, AmicaProtocolException> RULES =
            new PayloadRules<>(RejectReason.UNKNOWN_PAYLOAD, RejectReason.BAD_VALUE, AmicaProtocolException::new);

    /** Length of a Keep Alive payload. */
    public static final int KEEP_ALIVE_LENGTH = 16;
    /** Length of every other payload. */
    public static final int STATUS_LENGTH = PayloadRules.STATUS_LENGTH;

    private static final int KEEP_ALIVE = PayloadRules.type(82, 0);
    private static final int REED_SWITCH = PayloadRules.type(100, 3);
    private static final int MOTION = PayloadRules.type(100, 5);
    private static final int LIGHT = PayloadRules.type(5, 2);
    private static final int SPEAKER = PayloadRules.type(5, 4);
    private static final int HEATER = PayloadRules.type(5, 8);

    private AmicaPayloads() {
    }

    /**
     * @param payload a frame's payload
     * @return the decoded payload
     * @throws AmicaProtocolException {@link RejectReason#UNKNOWN_PAYLOAD} if the payload is shorter than two bytes
     *                                or its first two bytes name no known payload; {@link RejectReason#BAD_VALUE}
     *                                if a known payload has a wrong length, a non-zero third byte or a value out of
     *                                range
     */
    public static AmicaPayload decode(byte[] payload) throws AmicaProtocolException {
        int type = RULES.typeOf(payload);
        if (type == KEEP_ALIVE) {
            RULES.checkLength("keep-alive", payload, KEEP_ALIVE_LENGTH);
            return new KeepAlive(PayloadRules.u32(payload, 2), PayloadRules.u16(payload, 6),
                    PayloadRules.u16(payload, 8), PayloadRules.u16(payload, 10), PayloadRules.u32(payload, 12));
        }
        if (type == REED_SWITCH) {
            return new ReedSwitchStatus(RULES.flag("reed-switch status", payload, STATUS_LENGTH));
        }
        if (type == MOTION) {
            return new MotionDetection(RULES.flag("motion detection", payload, STATUS_LENGTH));
        }
        if (type == LIGHT) {
            return new LightControl(RULES.percent("light control", payload));
        }
        if (type == SPEAKER) {
            return new SpeakerControl(RULES.percent("speaker control", payload));
        }
        if (type == HEATER) {
            return new HeaterControl(RULES.percent("heater control", payload));
        }
        throw RULES.unknown(payload);
    }

    /**
     * @param payload a payload
     * @return its bytes: 16 for a {@link KeepAlive}, 4 for the others
     */
    public static byte[] encode(AmicaPayload payload) {
        Objects.requireNonNull(payload, "payload");
        if (payload instanceof KeepAlive k) {
            byte[] b = new byte[KEEP_ALIVE_LENGTH];
            b[0] = (byte) (KEEP_ALIVE >>> 8);
            PayloadRules.putU32(b, 2, k.uptimeSeconds());
            PayloadRules.putU16(b, 6, k.batteryMillivolts());
            PayloadRules.putU16(b, 8, k.vendorId());
            PayloadRules.putU16(b, 10, k.productId());
            PayloadRules.putU32(b, 12, k.serialNumber());
            return b;
        }
        if (payload instanceof ReedSwitchStatus r) {
            return PayloadRules.status(REED_SWITCH, r.open() ? 1 : 0);
        }
        if (payload instanceof MotionDetection m) {
            return PayloadRules.status(MOTION, m.detected() ? 1 : 0);
        }
        if (payload instanceof LightControl l) {
            return PayloadRules.status(LIGHT, l.percent());
        }
        if (payload instanceof SpeakerControl s) {
            return PayloadRules.status(SPEAKER, s.percent());
        }
        HeaterControl h = (HeaterControl) payload; // the interface is sealed: nothing else remains
        return PayloadRules.status(HEATER, h.percent());
    }
}

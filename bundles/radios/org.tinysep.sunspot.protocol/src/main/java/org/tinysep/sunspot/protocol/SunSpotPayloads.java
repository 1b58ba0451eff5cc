package org.tinysep.sunspot.protocol;

import java.util.Objects;
import org.tinysep.link.frame.PayloadRules;

/**
 * Converts between payload bytes (thesis Table 3.2, plus Movement Detection version 2 and the person node's reports of
 * protocol 2.2.0, see {@code PersonPayloads}) and {@link SunSpotPayload}
 * records. A payload is named by its first two bytes: the sensor type and the payload version. Lengths are exact
 * (10 bytes for Movement Detection version 2, 4 for the others), the third byte is 0 where the table shows it, and
 * values must be in range. Multi-byte numbers are signed 16-bit big-endian. Stateless and thread-safe.
 * <p>
 * The rules and number formats are shared with the AmICA protocol ({@code org.tinysep.link.frame.PayloadRules});
 * this class keeps the Sun SPOT payload table.
 */
public final class SunSpotPayloads {

    private static final PayloadRules<RejectReason, SunSpotProtocolException> RULES =
            new PayloadRules<>(RejectReason.UNKNOWN_PAYLOAD, RejectReason.BAD_VALUE, SunSpotProtocolException::new);

    /** Length of every version 1 payload. */
    public static final int STATUS_LENGTH = PayloadRules.STATUS_LENGTH;
    /** Length of a Movement Detection version 2 payload (with coordinates). */
    public static final int MOVEMENT_V2_LENGTH = 10;

    private static final int MOVEMENT_V1 = PayloadRules.type(2, 1);
    private static final int MOVEMENT_V2 = PayloadRules.type(2, 2);
    private static final int TEMPERATURE = PayloadRules.type(3, 1);
    private static final int LIGHT = PayloadRules.type(4, 1);
    private static final int PET_MOVEMENT = PayloadRules.type(5, 1);
    private static final int MIN_TENTHS = -400;
    private static final int MAX_TENTHS = 1250;

    private SunSpotPayloads() {
    }

    /**
     * @param payload a frame's payload
     * @return the decoded payload
     * @throws SunSpotProtocolException {@link RejectReason#UNKNOWN_PAYLOAD} if the payload is shorter than two bytes
     *                                  or its first two bytes name no known payload; {@link RejectReason#BAD_VALUE}
     *                                  if a known payload has a wrong length, a non-zero third byte or a value out
     *                                  of range
     */
    public static SunSpotPayload decode(byte[] payload) throws SunSpotProtocolException {
        int type = RULES.typeOf(payload);
        if (type == MOVEMENT_V1) {
            return new MovementDetection(RULES.flag("movement detection", payload, STATUS_LENGTH));
        }
        if (type == MOVEMENT_V2) {
            boolean detected = RULES.flag("movement detection v2", payload, MOVEMENT_V2_LENGTH);
            return new MovementDetection(detected, new Position(PayloadRules.s16(payload, 4),
                    PayloadRules.s16(payload, 6), PayloadRules.s16(payload, 8)));
        }
        if (type == TEMPERATURE) {
            RULES.checkLength("temperature status", payload, STATUS_LENGTH);
            int tenths = PayloadRules.s16(payload, 2);
            if (tenths < MIN_TENTHS || tenths > MAX_TENTHS) {
                throw RULES.badValue("temperature status value " + tenths + " tenths of a degree, expected -400..1250");
            }
            return TemperatureStatus.ofTenths(tenths);
        }
        if (type == LIGHT) {
            return new LightStatus(RULES.percent("light status", payload));
        }
        if (type == PET_MOVEMENT) {
            return new PetMovementDetection(RULES.flag("pet movement detection", payload, STATUS_LENGTH));
        }
        SunSpotPayload person = PersonPayloads.decode(RULES, type, payload);
        if (person != null) {
            return person;
        }
        throw RULES.unknown(payload);
    }

    /**
     * @param payload a payload
     * @return its bytes: 10 for a {@link MovementDetection} with a position, 14 for a {@link MovementSummaryReport},
     *         8 + 6 per sample for a {@link BurstChunk}, 4 for the others
     */
    public static byte[] encode(SunSpotPayload payload) {
        Objects.requireNonNull(payload, "payload");
        if (payload instanceof MovementDetection m) {
            if (m.position() == null) {
                return PayloadRules.status(MOVEMENT_V1, m.detected() ? 1 : 0);
            }
            byte[] b = new byte[MOVEMENT_V2_LENGTH];
            PayloadRules.putU16(b, 0, MOVEMENT_V2);
            b[3] = (byte) (m.detected() ? 1 : 0);
            PayloadRules.putU16(b, 4, m.position().xCentimetres());
            PayloadRules.putU16(b, 6, m.position().yCentimetres());
            PayloadRules.putU16(b, 8, m.position().zCentimetres());
            return b;
        }
        if (payload instanceof TemperatureStatus t) {
            byte[] b = PayloadRules.status(TEMPERATURE, 0);
            PayloadRules.putU16(b, 2, t.tenths());
            return b;
        }
        if (payload instanceof LightStatus l) {
            return PayloadRules.status(LIGHT, l.percent());
        }
        if (payload instanceof PetMovementDetection p) {
            return PayloadRules.status(PET_MOVEMENT, p.detected() ? 1 : 0);
        }
        return PersonPayloads.encode(payload); // the interface is sealed: only the person node's reports remain
    }
}

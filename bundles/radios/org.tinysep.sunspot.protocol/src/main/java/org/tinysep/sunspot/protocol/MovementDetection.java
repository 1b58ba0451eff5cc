package org.tinysep.sunspot.protocol;

/**
 * Movement Detection payload, sent by the movement sensor node.
 * <ul>
 * <li>Version 1 (thesis Table 3.2): {@code 2 1 0 A}, A = 1 motion, A = 0 none. {@link #position()} is null.</li>
 * <li>Version 2 (TinySEP extension for {@code MovementWithCoordinates}, thesis 3.5):
 * {@code 2 2 0 A X1 X2 Y1 Y2 Z1 Z2}, the coordinates as signed 16-bit big-endian centimetres.</li>
 * </ul>
 *
 * @param detected true if a motion was detected
 * @param position where, in centimetres; null for version 1
 */
public record MovementDetection(boolean detected, Position position) implements SunSpotPayload {

    /**
     * A version 1 payload: no position.
     *
     * @param detected true if a motion was detected
     */
    public MovementDetection(boolean detected) {
        this(detected, null);
    }

    /** @return 2 if a position is carried, else 1 */
    public int version() {
        return position == null ? 1 : 2;
    }

    @Override
    public SunSpotSensorType sensorType() {
        return SunSpotSensorType.MOVEMENT;
    }
}

package org.tinysep.sunspot.protocol;

/**
 * Person node button report {@code 6 0x11 B A} (TinySEP, protocol 2.2.0): switch B (1 or 2, the Sun SPOT's SW1 and
 * SW2) was pressed (A = 1) or released (A = 0). The node sends one report on each change.
 *
 * @param button  1 or 2
 * @param pressed true for pressed, false for released
 */
public record ButtonReport(int button, boolean pressed) implements SunSpotPayload {

    /** @throws IllegalArgumentException if the button is not 1 or 2 */
    public ButtonReport {
        if (button < 1 || button > 2) {
            throw new IllegalArgumentException("a Sun SPOT has switches 1 and 2, not " + button);
        }
    }

    @Override
    public SunSpotSensorType sensorType() {
        return SunSpotSensorType.PERSON;
    }
}

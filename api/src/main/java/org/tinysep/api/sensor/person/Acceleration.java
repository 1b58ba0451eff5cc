package org.tinysep.api.sensor.person;

/**
 * One acceleration sample or mean in thousandths of standard gravity (milli-g), in the node's own axes. At rest
 * the vector points up with a length of about 1000.
 *
 * @param xMg x axis, milli-g
 * @param yMg y axis, milli-g
 * @param zMg z axis, milli-g
 */
public record Acceleration(int xMg, int yMg, int zMg) {

    /** @return the length of the vector, milli-g */
    public double magnitudeMg() {
        return Math.sqrt((double) xMg * xMg + (double) yMg * yMg + (double) zMg * zMg);
    }
}

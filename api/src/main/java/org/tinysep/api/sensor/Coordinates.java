package org.tinysep.api.sensor;

/**
 * A position in the flat in metres, in the house's own frame of reference.
 *
 * @param x metres east
 * @param y metres north
 * @param z metres up
 */
public record Coordinates(double x, double y, double z) {
}

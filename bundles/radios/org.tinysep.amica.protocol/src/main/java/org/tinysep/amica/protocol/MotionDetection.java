package org.tinysep.amica.protocol;

/**
 * Movement Detection and Pet Movement Detection payload {@code 100 5 0 A}: A = 1 motion, A = 0 none. The thesis
 * gives both the same bytes; the sending node's type (movement or pet collar) tells which one it is.
 *
 * @param detected true if a motion was detected
 */
public record MotionDetection(boolean detected) implements AmicaPayload {
}

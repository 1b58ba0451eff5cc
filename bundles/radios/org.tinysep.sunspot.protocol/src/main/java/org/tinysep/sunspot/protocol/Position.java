package org.tinysep.sunspot.protocol;

/**
 * Where a movement was detected, in centimetres, as carried by Movement Detection version 2 ({@code 2 2 0 A X1 X2
 * Y1 Y2 Z1 Z2}, each coordinate a signed 16-bit big-endian number). The origin and the axes are fixed by whoever
 * installs the node; the protocol only carries the numbers.
 *
 * @param xCentimetres x, -32768..32767 cm
 * @param yCentimetres y, -32768..32767 cm
 * @param zCentimetres z, -32768..32767 cm
 */
public record Position(int xCentimetres, int yCentimetres, int zCentimetres) {

    /** @throws IllegalArgumentException if a coordinate does not fit a signed 16-bit number */
    public Position {
        check("xCentimetres", xCentimetres);
        check("yCentimetres", yCentimetres);
        check("zCentimetres", zCentimetres);
    }

    private static void check(String name, int value) {
        if (value < Short.MIN_VALUE || value > Short.MAX_VALUE) {
            throw new IllegalArgumentException(name + " " + value + " is outside -32768..32767");
        }
    }
}

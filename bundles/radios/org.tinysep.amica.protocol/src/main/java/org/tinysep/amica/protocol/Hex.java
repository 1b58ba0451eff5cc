package org.tinysep.amica.protocol;

/** This package's name for {@link org.tinysep.link.frame.Hex}, shared with the other protocol family. */
final class Hex {

    private Hex() {
    }

    static String of(byte[] bytes, int off, int len) {
        return org.tinysep.link.frame.Hex.of(bytes, off, len);
    }
}

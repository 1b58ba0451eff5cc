package org.tinysep.sunspot.protocol;

import org.tinysep.link.frame.Reason;

/**
 * Why a frame or payload was rejected. Every rejection in this library names one of these, so the bus radio can log
 * and count rejections by cause. Each tells its rule in plain words: {@code description()} (written once in the
 * shared {@code org.tinysep.link.frame.Reason}).
 */
public enum RejectReason implements Reason {

    /** Fewer bytes than a frame needs: under 12 bytes, or under 12 + S. */
    TRUNCATED("frame shorter than its size identifier announces"),
    /** More bytes than the size identifier announces, or longer than the 267-byte maximum. */
    OVERSIZE("frame longer than its size identifier announces or than 267 bytes"),
    /** Size identifier S differs from the header's payload length L. */
    LENGTH_MISMATCH("size identifier differs from the header's payload length"),
    /** The checksum byte is not the CRC-8/SMBUS of the other frame bytes. */
    BAD_CHECKSUM("checksum (CRC-8/SMBUS) does not match the frame"),
    /** The header's sensor type differs from the payload's first byte, or the payload is empty. */
    TYPE_MISMATCH("header sensor type differs from the payload's first byte"),
    /** The payload (or, in a byte stream, the header's sensor type) is not one of thesis Table 3.2. */
    UNKNOWN_PAYLOAD("payload type is not one of thesis Table 3.2"),
    /** A known payload with a wrong length, a non-zero reserved byte or a value out of range. */
    BAD_VALUE("payload has a wrong length or a value out of range");

    RejectReason(String description) {
        Reason.describe(this, description);
    }
}

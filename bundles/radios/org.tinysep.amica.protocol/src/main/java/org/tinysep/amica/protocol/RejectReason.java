package org.tinysep.amica.protocol;

import org.tinysep.link.frame.Reason;

/**
 * Why a frame or payload was rejected. Every rejection in this library names one of these, so bus radios can log and
 * count rejections by cause. Each tells its rule in plain words: {@code description()} (written once in the shared
 * {@code org.tinysep.link.frame.Reason}).
 */
public enum RejectReason implements Reason {

    /** Fewer bytes than a frame needs: under 8 bytes, or under 8 + S. */
    TRUNCATED("frame shorter than its size identifier announces"),
    /** More bytes than the size identifier announces, or longer than the 263-byte maximum. */
    OVERSIZE("frame longer than its size identifier announces or than 263 bytes"),
    /** Header value is not 0xA1 (AmICA node protocol v1). */
    BAD_HEADER("header value is not 0xA1 (AmICA node protocol v1)"),
    /** Size identifier S differs from the header's payload length L. */
    LENGTH_MISMATCH("size identifier differs from the header's payload length"),
    /** The checksum byte is not the CRC-8/SMBUS of the other frame bytes. */
    BAD_CHECKSUM("checksum (CRC-8/SMBUS) does not match the frame"),
    /** Empty payload, or its first two bytes name no payload of thesis Table 3.1. */
    UNKNOWN_PAYLOAD("payload type is not one of thesis Table 3.1"),
    /** A known payload with a wrong length, a non-zero reserved byte or a value out of range. */
    BAD_VALUE("payload has a wrong length or a value out of range"),
    /** Used by bus radios: a packet from a node that has not announced itself with a keep-alive. */
    UNKNOWN_NODE("packet from an unknown node that is not a keep-alive");

    RejectReason(String description) {
        Reason.describe(this, description);
    }
}

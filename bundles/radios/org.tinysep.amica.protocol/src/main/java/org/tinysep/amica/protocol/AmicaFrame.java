package org.tinysep.amica.protocol;

import java.util.Arrays;
import java.util.Objects;

/**
 * One AmICA frame, decoded: the header fields that carry information plus the payload. The framing bytes (size
 * identifier, header value, checksum, payload length) are derived by {@link AmicaCodec#encode(AmicaFrame)}.
 * <p>
 * Immutable: the payload is copied on construction and on access; {@code equals}, {@code hashCode} and
 * {@code toString} use the payload's content.
 *
 * @param netgroup    the netgroup of sender and receiver, 0..255
 * @param source      the sender's address, 0..255 ({@value AmicaCodec#PLATFORM_ADDRESS} for the platform)
 * @param destination the receiver's address, 0..255 ({@value AmicaCodec#PLATFORM_ADDRESS} for the platform)
 * @param sequence    the sender's sequence number, 0..255 (wraps)
 * @param payload     the payload (thesis Table 3.1), at most {@value AmicaCodec#MAX_PAYLOAD} bytes; may be empty
 */
public record AmicaFrame(int netgroup, int source, int destination, int sequence, byte[] payload) {

    /** @throws IllegalArgumentException if a field is out of range; NullPointerException if payload is null */
    public AmicaFrame {
        AmicaAddress.checkByte("netgroup", netgroup);
        AmicaAddress.checkByte("source", source);
        AmicaAddress.checkByte("destination", destination);
        AmicaAddress.checkByte("sequence", sequence);
        Objects.requireNonNull(payload, "payload");
        if (payload.length > AmicaCodec.MAX_PAYLOAD) {
            throw new IllegalArgumentException(
                    "payload of " + payload.length + " bytes exceeds " + AmicaCodec.MAX_PAYLOAD);
        }
        payload = payload.clone();
    }

    /**
     * A frame from a node to the platform.
     *
     * @param node     the sending node
     * @param sequence the node's sequence number, 0..255
     * @param payload  the payload
     * @return the frame with destination {@value AmicaCodec#PLATFORM_ADDRESS}
     */
    public static AmicaFrame toPlatform(AmicaAddress node, int sequence, byte[] payload) {
        return new AmicaFrame(node.netgroup(), node.address(), AmicaCodec.PLATFORM_ADDRESS, sequence, payload);
    }

    /**
     * A command from the platform to a node.
     *
     * @param node     the receiving node
     * @param sequence the platform's sequence number, 0..255
     * @param payload  the payload
     * @return the frame with source {@value AmicaCodec#PLATFORM_ADDRESS}
     */
    public static AmicaFrame fromPlatform(AmicaAddress node, int sequence, byte[] payload) {
        return new AmicaFrame(node.netgroup(), AmicaCodec.PLATFORM_ADDRESS, node.address(), sequence, payload);
    }

    /** @return a copy of the payload */
    @Override
    public byte[] payload() {
        return payload.clone();
    }

    /** @return the payload length in bytes, without copying the payload */
    public int payloadLength() {
        return payload.length;
    }

    /** @return the sender's identity: (netgroup, source) */
    public AmicaAddress sender() {
        return AmicaAddress.of(netgroup, source); // shared, not one per frame
    }

    /** @return the receiver's identity: (netgroup, destination) */
    public AmicaAddress receiver() {
        return new AmicaAddress(netgroup, destination);
    }

    /** The payload itself, not a copy, for the codec; callers must not modify it. */
    byte[] payloadUnsafe() {
        return payload;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof AmicaFrame f && netgroup == f.netgroup && source == f.source
                && destination == f.destination && sequence == f.sequence && Arrays.equals(payload, f.payload);
    }

    @Override
    public int hashCode() {
        return Objects.hash(netgroup, source, destination, sequence) * 31 + Arrays.hashCode(payload);
    }

    /** @return e.g. {@code AmicaFrame[1.17 -> 1.0, seq=6, payload=64 05 00 01]} */
    @Override
    public String toString() {
        return "AmicaFrame[" + netgroup + "." + source + " -> " + netgroup + "." + destination + ", seq=" + sequence
                + ", payload=" + Hex.of(payload, 0, payload.length) + "]";
    }
}

package org.tinysep.api.packet;

import java.util.Optional;
import org.osgi.annotation.versioning.ConsumerType;

/**
 * Tells the packets of one node protocol in words, for the packet log's readers (the web console). A whiteboard
 * service: each bundle that speaks a protocol registers one (the AmICA bus radios, the Sun SPOT bus radio); a reader
 * asks every registered describer and shows a packet that none recognises undecoded, saying why. Several
 * registrations of the same {@link #protocol()} (two AmICA bus radios) are interchangeable.
 */
@ConsumerType
public interface PacketDescriber {

    /** @return the protocol's name as people say it, e.g. {@code AmICA}, {@code Sun SPOT} */
    String protocol();

    /**
     * Whether a packet logged under this origin is most likely of this protocol, so that this describer is asked
     * first (frames of two protocols can look alike). The default: no preference.
     *
     * @param origin the packet log's origin text, e.g. {@code node 0014.4F01.0000.A001 via udp …}
     */
    default boolean usualFor(String origin) {
        return false;
    }

    /**
     * @param bytes the packet as on the wire
     * @return the packet in words, e.g. {@code AmICA 1.17 → 1.0 #6: motion detected} (a frame whose payload is not
     *         understood says so and why); empty when the bytes are no frame of this protocol. Never throws for bad
     *         bytes.
     */
    Optional<String> describe(byte[] bytes);
}

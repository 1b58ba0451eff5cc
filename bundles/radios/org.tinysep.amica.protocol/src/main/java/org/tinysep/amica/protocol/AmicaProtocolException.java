package org.tinysep.amica.protocol;

import java.util.Objects;
import org.tinysep.link.frame.ProtocolException;

/**
 * Bad input against the AmICA node protocol; {@code reason()} is the broken {@link RejectReason}, never null. The
 * message, the missing stack trace and the typed accessor are the shared {@code ProtocolException}'s.
 */
public final class AmicaProtocolException extends ProtocolException implements ProtocolException.Typed<RejectReason> {

    private static final long serialVersionUID = 1L;

    /**
     * @param reason the broken rule
     * @param detail what exactly was wrong, e.g. {@code "checksum 0x12, computed 0x34"}; may be null
     */
    public AmicaProtocolException(RejectReason reason, String detail) {
        super(Objects.requireNonNull(reason, "reason"), reason.description(), detail);
    }
}

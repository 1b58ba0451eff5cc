package org.tinysep.amica.protocol;

import java.util.Objects;
import org.tinysep.link.frame.ProtocolException;

/**
 * Bad input: a frame or payload that violates the AmICA node protocol. The {@link #reason()} says which rule was
 * broken; the message adds the detail (which byte, which value). Created without a stack trace, since rejecting
 * garbage is an expected, frequent event on a radio link.
 */
public final class AmicaProtocolException extends ProtocolException {

    private static final long serialVersionUID = 1L;

    /**
     * @param reason the broken rule
     * @param detail what exactly was wrong, e.g. {@code "checksum 0x12, computed 0x34"}
     */
    public AmicaProtocolException(RejectReason reason, String detail) {
        super(Objects.requireNonNull(reason, "reason"), reason.description(), detail);
    }

    /** @return the broken rule, never null */
    @Override
    public RejectReason reason() {
        return (RejectReason) super.reason();
    }
}

package org.tinysep.amica.protocol;

import java.util.Objects;
import org.tinysep.link.frame.FrameFormat;

/**
 * Bad input: a frame or payload that violates the AmICA node protocol. The {@link #reason()} says which rule was
 * broken; the message adds the detail (which byte, which value). Created without a stack trace, since rejecting
 * garbage is an expected, frequent event on a radio link.
 */
public final class AmicaProtocolException extends Exception {

    private static final long serialVersionUID = 1L;

    private final RejectReason reason;

    /**
     * @param reason the broken rule
     * @param detail what exactly was wrong, e.g. {@code "checksum 0x12, computed 0x34"}
     */
    public AmicaProtocolException(RejectReason reason, String detail) {
        super(FrameFormat.message(Objects.requireNonNull(reason, "reason"), reason.description(), detail), null, false,
                false);
        this.reason = reason;
    }

    /** @return the broken rule, never null */
    public RejectReason reason() {
        return reason;
    }
}

package org.tinysep.link.frame;

import java.util.Objects;

/**
 * What the AmICA and the Sun SPOT protocol exceptions share: bad input, the broken rule (a family's reason enum)
 * and the message {@code "NAME (description): detail"} ({@link FrameFormat#message}). Created without a stack
 * trace, since rejecting garbage is an expected, frequent event on a radio link. Each family's exception adds only
 * its constructor and its typed {@code reason()}.
 */
public abstract class ProtocolException extends Exception {

    private static final long serialVersionUID = 1L;

    private final Enum<?> reason;

    /**
     * @param reason the broken rule, not null
     * @param description the rule in plain words
     * @param detail what exactly was wrong, e.g. {@code "checksum 0x12, computed 0x34"}; may be null
     */
    protected ProtocolException(Enum<?> reason, String description, String detail) {
        super(FrameFormat.message(Objects.requireNonNull(reason, "reason"), description, detail), null, false, false);
        this.reason = reason;
    }

    /** @return the broken rule, never null; each family narrows the type */
    public Enum<?> reason() {
        return reason;
    }
}

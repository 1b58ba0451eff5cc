package org.tinysep.link.frame;

import java.util.Objects;

/**
 * Bad input: a frame or payload that violates a node protocol (AmICA or Sun SPOT). The exception's {@code reason()}
 * says which rule was broken (one of the family's {@code RejectReason}s, never null); the message is
 * {@code "NAME (description): detail"} ({@link FrameFormat#message}), the detail saying which byte or which value.
 * Created without a stack trace, since rejecting garbage is an expected, frequent event on a radio link.
 * <p>
 * Everything is written here once: a family's exception is only its declaration and its constructor,
 * {@code class AmicaProtocolException extends ProtocolException implements Typed<RejectReason>}, and inherits its
 * typed {@code reason()} from {@link Typed} (a generic class may not extend {@code Throwable}, a generic interface
 * of one may).
 * <p>
 * A bundle that uses a family's exception calls {@code e.reason()} (or {@code e -> e.reason()}), never the method
 * reference {@code AmicaProtocolException::reason}: javac names the declaring interface in a method reference, so
 * the bundle would import this package, which no bundle exports (it is compiled into each protocol bundle), and
 * would not resolve. A call names the family's exception class, as before.
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

    /**
     * The typed accessor of a family's exception: {@code reason()} returns the family's reason enum.
     *
     * @param <R> the family's reason enum, the type its constructor takes
     */
    public interface Typed<R extends Enum<R>> {

        /** @return the broken rule, never null */
        @SuppressWarnings("unchecked") // only a ProtocolException implements it, its constructor taking an R
        default R reason() {
            return (R) ((ProtocolException) this).reason;
        }
    }
}

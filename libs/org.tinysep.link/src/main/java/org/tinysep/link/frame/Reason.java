package org.tinysep.link.frame;

import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A family's reject reason (the AmICA and the Sun SPOT {@code RejectReason} enums), written once: each constant's
 * constructor names its rule in plain words with {@link #describe}, and {@link #description()} tells them. An enum
 * cannot inherit a field, so the words are kept in one table of this package (one per protocol bundle, which
 * compiles this package in).
 * <p>
 * A bundle calls {@code reason.description()}, never the method reference {@code RejectReason::description}: it would
 * name this interface and make the bundle import this private package (see {@link ProtocolException}).
 */
public interface Reason {

    /**
     * Called once by each constant's constructor.
     *
     * @param reason      the constant, not null
     * @param description its rule in plain words, not null
     */
    static void describe(Reason reason, String description) {
        Words.OF.put(Objects.requireNonNull(reason, "reason"), Objects.requireNonNull(description, "description"));
    }

    /** @return a short human-readable explanation, suitable for a log entry */
    default String description() {
        return Words.OF.get(this);
    }
}

/** The words of every {@link Reason} constant made so far (enum constants hash by identity). */
final class Words {

    static final Map<Reason, String> OF = new ConcurrentHashMap<>();

    private Words() {
    }
}

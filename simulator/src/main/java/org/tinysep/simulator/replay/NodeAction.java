package org.tinysep.simulator.replay;

import java.time.LocalDateTime;
import java.util.Objects;

/**
 * One step of a {@link ReplayPlan}: at {@code time} (recorded local time, to be mapped onto virtual time) the node
 * enters {@code signal}'s state and sends its payload ({@link Signal#payload()}).
 *
 * @param time   when
 * @param node   which node
 * @param signal new state
 */
public record NodeAction(LocalDateTime time, NodeSpec node, Signal signal) {

    /** @throws NullPointerException if a field is null */
    public NodeAction {
        Objects.requireNonNull(time, "time");
        Objects.requireNonNull(node, "node");
        Objects.requireNonNull(signal, "signal");
    }
}

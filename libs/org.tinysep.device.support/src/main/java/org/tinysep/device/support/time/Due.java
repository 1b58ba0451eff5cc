package org.tinysep.device.support.time;

import java.time.Instant;

/**
 * A tick that says when it is next needed: a {@link PlatformTicker} calls it only at the first tick at or after the
 * time it returned, or earlier when the component {@linkplain PlatformTicker#wake woke it}.
 */
@FunctionalInterface
public interface Due {

    /**
     * @param now the platform time of this tick
     * @return the platform time of the next tick this component needs: a time not after {@code now} means every tick
     *         (as the plain {@code Consumer} ticker), {@code null} means none until {@link PlatformTicker#wake}
     */
    Instant tick(Instant now);

    /**
     * @return the earlier of two due times, where {@code null} means none (as {@link #tick} returns): the other one,
     *         or null when both are
     */
    static Instant earliest(Instant a, Instant b) {
        return a == null || b != null && b.isBefore(a) ? b : a;
    }
}

package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.Limit;
import org.tinysep.inactivity.internal.learn.Sighting;

/** Sets the limit of the quiet period that an activity begins: fixed (THESIS) or learned (LEARNED). */
interface LimitPolicy {

    /**
     * @param fixed the room's fixed limit from the configuration
     * @param now   the platform's time
     */
    Limit limitAfter(Sighting s, Duration fixed, Instant now);

    /** The flat became empty ({@code empty}) or occupied again at {@code at}. */
    default void occupancy(boolean empty, Instant at) {
    }

    /**
     * A bed mat ({@code bed}) or seat mat is ON or OFF now, its first report too (LEARNED in a home of several
     * residents: an activity in its room while it is ON is a resting person's,
     * {@link org.tinysep.inactivity.internal.learn.Residents}).
     */
    default void mat(String device, String room, boolean bed, boolean on) {
    }

    /** @return the {@link Detector} name */
    default String name() {
        return Detector.THESIS.name();
    }

    /** The thesis's fixed per-room limits (each room's words made once, {@link FixedLimits}). */
    static LimitPolicy thesis() {
        return new FixedLimits();
    }

    /** Learned limits; every activity is also learned from; answers reused until the next learning. */
    static LimitPolicy learned(LearnedLimits limits) {
        return learned(new CachedLimits(limits));
    }

    /** Learned limits through {@code cached} (one computation per room, hour and state per learning). */
    static LimitPolicy learned(CachedLimits cached) {
        LearnedLimits limits = cached.learned();
        return new LimitPolicy() {
            @Override
            public Limit limitAfter(Sighting s, Duration fixed, Instant now) {
                Sighting read = limits.residents().read(s);
                Limit l = cached.limitAfter(read, fixed, now);
                return limits.residents().explain(s, read, l);
            }

            @Override
            public void mat(String device, String room, boolean bed, boolean on) {
                limits.residents().mat(device, room, bed, on);
            }

            @Override
            public String name() {
                return Detector.LEARNED.name();
            }

            @Override
            public void occupancy(boolean empty, Instant at) {
                limits.history().occupancy(empty, at);
            }
        };
    }
}

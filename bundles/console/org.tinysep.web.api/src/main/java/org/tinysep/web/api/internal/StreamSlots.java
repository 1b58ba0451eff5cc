package org.tinysep.web.api.internal;

import java.util.HashMap;
import java.util.Map;
import org.tinysep.web.api.internal.Sessions.Session;

/**
 * The live-stream slots of one log: at most {@value #TOTAL} streams, at most
 * {@value #PER_SESSION} per login session (a browser needs one per open tab), and the caregiver's sessions together
 * at most {@code TOTAL - }{@value #KEPT_FOR_INSTALLER}, so the installer can always open one even when caregivers
 * (or someone with the caregiver's password) hold every other slot.
 */
final class StreamSlots {

    static final int TOTAL = 16;
    static final int PER_SESSION = 4;
    static final int KEPT_FOR_INSTALLER = 4;

    private final Map<String, Integer> perSession = new HashMap<>();
    private final Map<Role, Integer> perRole = new HashMap<>();
    private int total;

    /**
     * Takes a slot for {@code session}.
     *
     * @throws ApiException 503 saying which limit was reached and what to do
     */
    synchronized void take(Session session) {
        if (perSession.getOrDefault(session.token(), 0) >= PER_SESSION) {
            throw new ApiException(503, "this login already has " + PER_SESSION + " live streams of this log open: "
                    + "close another console tab");
        }
        if (session.role() != Role.INSTALLER && perRole.getOrDefault(session.role(), 0) >= TOTAL - KEPT_FOR_INSTALLER) {
            throw new ApiException(503, "the " + session.role().id() + " logins have " + (TOTAL - KEPT_FOR_INSTALLER)
                    + " live streams of this log open, the most they may (the others are kept for the installer): "
                    + "close a console tab");
        }
        if (total >= TOTAL) {
            throw new ApiException(503, "too many open live streams (" + TOTAL + "); close a console tab");
        }
        perSession.merge(session.token(), 1, Integer::sum);
        perRole.merge(session.role(), 1, Integer::sum);
        total++;
    }

    /** Gives back a slot {@link #take} gave {@code session}. */
    synchronized void release(Session session) {
        perSession.computeIfPresent(session.token(), (k, n) -> n <= 1 ? null : n - 1);
        perRole.computeIfPresent(session.role(), (k, n) -> n <= 1 ? null : n - 1);
        total = Math.max(0, total - 1);
    }

    synchronized int total() {
        return total;
    }
}

package org.tinysep.api.service;

import java.time.Instant;
import java.util.Objects;

/**
 * A raised inactivity alert.
 *
 * @param roomUid        the room of the last activity (empty if the device had no room)
 * @param roomName       its name for people
 * @param lastActivity   what the last activity was, e.g. "movement by Bathroom movement sensor"
 * @param lastActivityAt when it happened
 * @param raisedAt       when the alert was raised
 * @param explanation    why this quiet period is unusual, in plain words: the limit that was reached and how it
 *                       was set or learned, e.g. "usually at most 40 min between 13:00 and 16:00 in Bathroom, from
 *                       21 days ..." (empty when not known; since 1.1)
 */
public record InactivityAlert(String roomUid, String roomName, String lastActivity, Instant lastActivityAt,
        Instant raisedAt, String explanation) {

    public InactivityAlert {
        Objects.requireNonNull(lastActivityAt, "lastActivityAt");
        Objects.requireNonNull(raisedAt, "raisedAt");
        explanation = explanation == null ? "" : explanation;
    }

    /** An alert without an explanation (the 1.0 form). */
    public InactivityAlert(String roomUid, String roomName, String lastActivity, Instant lastActivityAt,
            Instant raisedAt) {
        this(roomUid, roomName, lastActivity, lastActivityAt, raisedAt, "");
    }
}

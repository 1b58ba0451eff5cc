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
 */
public record InactivityAlert(String roomUid, String roomName, String lastActivity, Instant lastActivityAt,
        Instant raisedAt) {

    public InactivityAlert {
        Objects.requireNonNull(lastActivityAt, "lastActivityAt");
        Objects.requireNonNull(raisedAt, "raisedAt");
    }
}

package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.Objects;

/**
 * One observed activity, already placed in its room.
 *
 * @param roomUid     the room's UID, empty when the reporting device has no room
 * @param roomName    the room's name for people (e.g. "Bathroom", or "unknown room (device Hall sensor)")
 * @param description what happened, e.g. "movement by Bathroom sensor"
 * @param at          when it happened
 * @param limit       how long inactivity may last after it before help is called
 * @param explanation why that limit, in plain words (empty when not known, e.g. restored from an old backup)
 */
record Activity(String roomUid, String roomName, String description, Instant at, Duration limit,
        String explanation) {

    Activity(String roomUid, String roomName, String description, Instant at, Duration limit) {
        this(roomUid, roomName, description, at, limit, "");
    }

    /** @return this activity moved to {@code when} (the clock went back) */
    Activity at(Instant when) {
        return new Activity(roomUid, roomName, description, when, limit, explanation);
    }

    Activity {
        Objects.requireNonNull(roomUid, "roomUid");
        Objects.requireNonNull(roomName, "roomName");
        Objects.requireNonNull(description, "description");
        Objects.requireNonNull(at, "at");
        explanation = explanation == null ? "" : explanation;
        if (limit == null || limit.isNegative() || limit.isZero()) {
            throw new IllegalArgumentException("limit must be positive, was " + limit);
        }
    }
}

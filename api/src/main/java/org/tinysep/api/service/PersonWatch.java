package org.tinysep.api.service;

import java.time.Instant;
import java.util.Objects;
import java.util.Optional;

/**
 * How Inactivity Recognition watches one wearer of a person node: the node's movement is that
 * person's activity; room-sensor activity counts for them only when no other wearer's node was moving at the time
 * (or, while their node is not worn, always). Since 1.2.
 *
 * @param person       the wearer's name (the person node's parameter {@code person})
 * @param nodeUid      the person node's device UID
 * @param worn         false after the node lay still for the configured time while room activity that nobody else
 *                     explained went on ("seems not to be worn"); the person is then watched by the room sensors
 * @param lastMovement when the node last moved, or when it was first heard if it has not moved since
 * @param lastRoom     the room where the person was last seen (the last room activity counted for them), if any
 * @param state        the person's own watch: {@link InactivityState#ALERT} when they have not been active for
 *                     longer than the limit of that room
 */
public record PersonWatch(String person, String nodeUid, boolean worn, Instant lastMovement,
        Optional<String> lastRoom, InactivityState state) {

    public PersonWatch {
        Objects.requireNonNull(person, "person");
        Objects.requireNonNull(nodeUid, "nodeUid");
        Objects.requireNonNull(lastMovement, "lastMovement");
        Objects.requireNonNull(lastRoom, "lastRoom");
        Objects.requireNonNull(state, "state");
    }
}

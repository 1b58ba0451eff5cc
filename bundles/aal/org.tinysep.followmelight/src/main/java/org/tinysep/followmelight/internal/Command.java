package org.tinysep.followmelight.internal;

import java.util.Objects;

/**
 * What the algorithm asks for: the lights of one room on or off.
 *
 * @param roomUid the room
 * @param on      on or off
 * @param reason  why, for the event log
 */
record Command(String roomUid, boolean on, String reason) {

    Command {
        Objects.requireNonNull(roomUid, "roomUid");
        Objects.requireNonNull(reason, "reason");
    }
}

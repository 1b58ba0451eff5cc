package org.tinysep.simulator.agent;

/** What a scenario line makes happen. */
public enum Action {
    /** walk to a room (arriving first when away) */
    GO,
    /** be in the first room, then walk to the second */
    FROM_TO,
    /** walk to the outer door and leave the flat */
    LEAVES,
    /** come in through the outer door, then walk to the room if one is given */
    ARRIVES,
    /** walk to the room if one is given, then lie still: no motion until {@link #WAKES} */
    COLLAPSES,
    /** walk to the room if one is given, then rest without motion (sleep) until {@link #WAKES} */
    SLEEPS,
    /** get up after sleeping or collapsing */
    WAKES,
    /** switch a node's battery off (empty: silent) or on again */
    BATTERY
}

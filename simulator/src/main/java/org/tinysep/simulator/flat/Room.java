package org.tinysep.simulator.flat;

import java.util.List;

/** A room of the house plan (thesis Figure 3.7): UID, name, type and the UIDs of its neighbours. */
public record Room(String uid, String name, String type, List<String> neighbourUids) {

    public Room {
        neighbourUids = List.copyOf(neighbourUids);
    }
}

package org.tinysep.inactivity.internal.learn;

import java.time.Instant;
import java.util.Objects;

/**
 * One sign of life in the home's history or live: something happened in a room (motion, a door or window change,
 * a mat, flush or appliance), or a bed mat says the person lies in bed.
 *
 * @param at       when
 * @param room     the room's UID (or any stable key; empty when the device has no room)
 * @param roomName the room's name for people, e.g. "Bathroom"
 * @param roomType the room's type, e.g. "Bedroom" (empty when unknown)
 * @param inBed    true when a bed mat reported the person in bed
 */
public record Sighting(Instant at, String room, String roomName, String roomType, boolean inBed) {

    public Sighting {
        Objects.requireNonNull(at, "at");
        room = room == null ? "" : room;
        roomName = roomName == null ? "" : roomName;
        roomType = roomType == null ? "" : roomType;
    }
}

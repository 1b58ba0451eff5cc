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
 * @param seated   true when a seat mat turned ON with this activity: the person is there and resting (sitting),
 *                 a quiet period that is normal for a resting person, not for one moving about
 * @param upFromBed true when a bed mat turned OFF with this activity: the person got up, so sleep ends, also in
 *                 the bedroom at night
 */
public record Sighting(Instant at, String room, String roomName, String roomType, boolean inBed, boolean seated,
        boolean upFromBed) {

    /** A sighting that is no bed mat turning OFF. */
    public Sighting(Instant at, String room, String roomName, String roomType, boolean inBed, boolean seated) {
        this(at, room, roomName, roomType, inBed, seated, false);
    }

    /** A sighting that is no seat mat turning ON. */
    public Sighting(Instant at, String room, String roomName, String roomType, boolean inBed) {
        this(at, room, roomName, roomType, inBed, false, false);
    }

    public Sighting {
        Objects.requireNonNull(at, "at");
        room = room == null ? "" : room;
        roomName = roomName == null ? "" : roomName;
        roomType = roomType == null ? "" : roomType;
    }
}

package org.tinysep.house.codec;

import java.util.List;
import java.util.Objects;

/**
 * What a house file holds: its rooms in file order. Nothing is checked beyond the format (unique UIDs, known
 * neighbours and the like are the reader's business: House Information and the simulator check them differently).
 *
 * @param rooms the {@code <ROOM>} elements in file order
 */
public record HouseRooms(List<HouseRoom> rooms) {

    /** A house without rooms ({@code <HOUSE_ROOMS/>}). */
    public static final HouseRooms EMPTY = new HouseRooms(List.of());

    public HouseRooms {
        rooms = List.copyOf(Objects.requireNonNull(rooms, "rooms"));
    }
}

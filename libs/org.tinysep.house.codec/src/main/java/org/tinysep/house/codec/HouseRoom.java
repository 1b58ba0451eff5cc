package org.tinysep.house.codec;

import java.util.List;
import java.util.Objects;

/**
 * One {@code <ROOM>} of a house file. Read values are stripped of surrounding white space; an element that is
 * missing reads as the empty text.
 *
 * @param uid        {@code <UID>}
 * @param name       {@code <NAME>}
 * @param type       {@code <TYPE>}
 * @param neighbours the {@code <ROOM_UID>}s of {@code <NEIGHBORS>} in file order
 */
public record HouseRoom(String uid, String name, String type, List<String> neighbours) {

    public HouseRoom {
        Objects.requireNonNull(uid, "uid");
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(type, "type");
        neighbours = List.copyOf(Objects.requireNonNull(neighbours, "neighbours"));
    }
}

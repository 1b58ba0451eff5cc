package org.tinysep.evaluation;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.UUID;
import org.tinysep.house.codec.HouseRoom;
import org.tinysep.house.codec.HouseRooms;
import org.tinysep.house.codec.HouseXml;

/**
 * A House Information file (format of {@code org.tinysep.houseinformation}) for a recorded home that brings none:
 * one room per mapped room name, its type guessed from the name ({@link #typeOf}: the room types Inactivity
 * Recognition has limits for, and {@code Bedroom}, which its sleep state needs), else the name itself (then the
 * default limit applies), written by the platform's house codec ({@code org.tinysep.house.codec}). No neighbour
 * links: the data gives no floor plan and the evaluation does not use them.
 */
final class HouseFile {

    private HouseFile() {
    }

    static Path write(Collection<String> rooms, Path file) throws IOException {
        List<HouseRoom> list = new ArrayList<>();
        for (String r : rooms) {
            String uid = UUID.nameUUIDFromBytes(("room " + r).getBytes(StandardCharsets.UTF_8)).toString();
            list.add(new HouseRoom(uid, r, typeOf(r), List.of()));
        }
        Files.write(file, HouseXml.toBytes(new HouseRooms(list)));
        return file;
    }

    /**
     * @return the room type a recorded room's name says ({@code Master bedroom} → {@code Bedroom}, {@code WC} →
     *         {@code Bathroom}, {@code Lounge} → {@code Living room}, {@code Entrance} → {@code Hall}, ...), else the
     *         name; the first match in this order: bedroom, bathroom, kitchen, living room, hall
     */
    static String typeOf(String room) {
        String r = room.toLowerCase(java.util.Locale.ROOT);
        if (r.contains("bed")) {
            return "Bedroom";
        }
        if (r.matches(".*(bath|toilet|shower|restroom|lavatory).*") || r.matches("(.*\\W)?wc(\\W.*)?")) {
            return "Bathroom";
        }
        if (r.matches(".*(kitchen|cook|pantry).*")) {
            return "Kitchen";
        }
        if (r.matches(".*(living|lounge|sitting|family|\\btv\\b|\\bden\\b|salon).*")) {
            return "Living room";
        }
        return r.matches(".*(hall|entrance|entry|corridor|foyer|porch|vestibule|landing).*") ? "Hall" : room;
    }
}

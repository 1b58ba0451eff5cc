package org.tinysep.houseinformation.internal;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import org.tinysep.api.service.Room;
import org.tinysep.house.codec.HouseRoom;
import org.tinysep.house.codec.HouseRooms;
import org.tinysep.house.codec.HouseXml;
import org.tinysep.house.codec.HouseXmlException;

/**
 * The house file (thesis Figure 3.7) as a {@link HousePlan}: the format is the house codec's
 * ({@code org.tinysep.house.codec}, compiled in), the checks of a valid plan are {@link HousePlan#of}'s.
 */
final class HouseCodec {

    /** @return the plan in {@code xml}; {@code source} names the file in messages */
    HousePlan read(byte[] xml, String source) throws MalformedHouseException {
        HouseRooms house;
        try {
            house = HouseXml.read(xml, source);
        } catch (HouseXmlException e) {
            throw new MalformedHouseException(e.getMessage(), e);
        }
        List<Room> rooms = new ArrayList<>();
        for (HouseRoom r : house.rooms()) {
            rooms.add(new Room(r.uid(), r.name(), r.type(), new LinkedHashSet<>(r.neighbours())));
        }
        try {
            return HousePlan.of(rooms);
        } catch (IllegalArgumentException e) {
            throw new MalformedHouseException(source + ": " + e.getMessage(), e);
        }
    }

    /** @return the plan as UTF-8 XML, neighbours in plan order; equal plans give equal bytes */
    byte[] write(HousePlan plan) {
        List<HouseRoom> rooms = new ArrayList<>();
        for (Room r : plan.rooms()) {
            rooms.add(new HouseRoom(r.uid(), r.name(), r.type(), plan.orderedNeighbours(r)));
        }
        return HouseXml.toBytes(new HouseRooms(rooms));
    }
}

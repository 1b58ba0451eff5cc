package org.tinysep.houseinformation.internal;

import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceReference;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.lifecycle.ServiceUse;
import org.tinysep.device.support.rooms.RoomDirectory;
import org.tinysep.device.support.rooms.Rooms;

/** One attempt to place one device by a rule, and its outcome. */
record Placement(Result result, String detail) {

    enum Result { PLACED, UNKNOWN_ROOM, NOT_YET, SKIPPED }

    static Placement apply(BundleContext context, ServiceReference<Device> ref, PlacementRules.Rule rule,
            HouseInformationProvider house) {
        if (house == null) {
            return new Placement(Result.NOT_YET, RoomDirectory.NO_HOUSE);
        }
        Room room;
        try {
            room = Rooms.resolve(house.rooms(), rule.room());
        } catch (IllegalArgumentException e) {
            return new Placement(Result.UNKNOWN_ROOM, e.getMessage());
        }
        // given back at once, leaving no use in the registry per device
        return ServiceUse.with(context, ref, device -> placeOn(device, room),
                new Placement(Result.SKIPPED, "the device is gone"));
    }

    private static Placement placeOn(Device device, Room room) {
        if (device.parameters().stream().map(Parameter::key).noneMatch("room"::equals)) {
            return new Placement(Result.SKIPPED, "the device has no room parameter");
        }
        try {
            device.setParameter("room", room.uid());
            return new Placement(Result.PLACED, room.name());
        } catch (IllegalArgumentException e) { // the device does not see House Information yet, or a room race
            return new Placement(Result.NOT_YET, e.getMessage());
        }
    }
}

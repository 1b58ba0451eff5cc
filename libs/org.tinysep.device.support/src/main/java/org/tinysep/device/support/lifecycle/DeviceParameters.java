package org.tinysep.device.support.lifecycle;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BiConsumer;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;

/**
 * A device's parameters: the {@code name} and {@code room} every device has (room only when
 * {@link AbstractDevice#placeable()}), followed by the device's own ({@link AbstractDevice#moreParameters()},
 * {@link AbstractDevice#applyParameter(String, String)}).
 */
final class DeviceParameters {

    static final String NAME = "name";

    private final AbstractDevice device;
    private final RoomPlacement room;
    private volatile String name;

    /**
     * @param property sets a service property on all the device's services (the room's UID)
     * @param roomChanged told when the room changed by itself (the room was removed from the house)
     */
    DeviceParameters(AbstractDevice device, String name, BiConsumer<String, Object> property, Runnable roomChanged) {
        this.device = device;
        this.name = name;
        this.room = new RoomPlacement(device.uid(), device.context, property, roomChanged);
    }

    String name() {
        return name;
    }

    /** @return the UID of the room the device is placed in, or null */
    String roomUid() {
        return room.roomUid();
    }

    /** @return the room UID to keep in the backup: null when unplaced or not placeable */
    String savedRoomUid() {
        return device.placeable() ? room.roomUid() : null;
    }

    List<Parameter> list() {
        List<Parameter> all = new ArrayList<>();
        all.add(Parameter.writable(NAME, name, "name shown to the user"));
        if (device.placeable()) {
            all.add(room.parameter());
        }
        all.addAll(device.moreParameters());
        if (device.watchesThePerson()) {
            all.add(Parameter.readOnly(LostSources.PARAMETER, device.roomsNotSeen(), "rooms this service can no "
                    + "longer see because their sensor went away (each also a 'Monitoring reduced' problem); empty "
                    + "when every sensor it had is there"));
        }
        return all;
    }

    void set(String key, String value) {
        if (NAME.equals(key)) {
            if (value == null || value.isBlank()) {
                throw new IllegalArgumentException("name must not be blank");
            }
            int bad = halfCharacter(value);
            if (bad >= 0) { // a lone surrogate would break the backup writer and be saved corrupted
                throw new IllegalArgumentException("name has a broken character at position " + (bad + 1)
                        + " (half of a UTF-16 surrogate pair, U+" + Integer.toHexString(value.charAt(bad))
                        .toUpperCase() + "): type the name again");
            }
            name = value.strip();
            device.context.reporter().event(EventKind.DEVICE_EVENT, device.uid(), "renamed to \"" + name + "\"");
        } else if (RoomPlacement.KEY.equals(key) && device.placeable()) {
            room.set(value);
        } else {
            device.applyParameter(key, value);
        }
    }

    /** @return the index of the first lone surrogate in {@code s} (it cannot be written as UTF-8), or -1 */
    static int halfCharacter(String s) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (Character.isHighSurrogate(c) && i + 1 < s.length() && Character.isLowSurrogate(s.charAt(i + 1))) {
                i++;
            } else if (Character.isSurrogate(c)) {
                return i;
            }
        }
        return -1;
    }

    /** Takes the saved name, before the device registers; a blank one is ignored. */
    void restoreName(String saved) {
        if (!saved.isBlank()) {
            name = saved;
        }
    }

    /** Takes the saved room, before the device registers; ignored when the device is not placeable. */
    void restoreRoom(String uid) {
        if (device.placeable()) {
            room.restore(uid);
        }
    }

    IllegalArgumentException unknown(String key) {
        List<String> writable = list().stream().filter(Parameter::writable).map(Parameter::key).toList();
        return new IllegalArgumentException("unknown or read-only parameter '" + key + "' of " + device.type()
                + "; writable: " + String.join(", ", writable));
    }

    /** Stops watching the house; called when the device goes. */
    void close() {
        room.close();
    }
}

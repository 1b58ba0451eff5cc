package org.tinysep.runtime.internal.directory;

import java.lang.reflect.Array;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.function.Function;
import org.tinysep.api.device.DeviceProperties;

/**
 * The hardware-node and placement properties of a device service ({@link DeviceProperties#NODE_TYPE},
 * {@link DeviceProperties#NODE_ADDRESS}, {@link DeviceProperties#ROOM}); empty strings and lists when absent.
 */
public record NodeInfo(List<String> types, String address, String room) {

    public static final NodeInfo NONE = new NodeInfo(List.of(), "", "");

    public NodeInfo {
        types = List.copyOf(types);
        address = address == null ? "" : address;
        room = room == null ? "" : room;
    }

    /** Reads the properties through {@code property} (e.g. {@code ServiceReference::getProperty}). */
    static NodeInfo from(Function<String, Object> property) {
        Object address = property.apply(DeviceProperties.NODE_ADDRESS);
        Object room = property.apply(DeviceProperties.ROOM);
        return new NodeInfo(strings(property.apply(DeviceProperties.NODE_TYPE)),
                address == null ? "" : address.toString(), room == null ? "" : room.toString());
    }

    public boolean isEmpty() {
        return types.isEmpty() && address.isEmpty() && room.isEmpty();
    }

    /** @return a String, String[], other array or Collection property as a list of strings */
    static List<String> strings(Object value) {
        List<String> out = new ArrayList<>();
        if (value == null) {
            return out;
        } else if (value.getClass().isArray()) {
            for (int i = 0; i < Array.getLength(value); i++) {
                add(out, Array.get(value, i));
            }
        } else if (value instanceof Collection<?> c) {
            c.forEach(v -> add(out, v));
        } else {
            add(out, value);
        }
        return out;
    }

    private static void add(List<String> out, Object v) {
        if (v != null && !v.toString().isEmpty()) {
            out.add(v.toString());
        }
    }
}

package org.tinysep.amica.presence.internal;

import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.sensor.presence.PresenceKind;

/** What a presence node observes, from the node types its keep-alive announced. */
final class PresenceNodeKind {

    /** The order in which a node announcing several presence types is read (the first wins). */
    private static final List<PresenceKind> ORDER = List.of(PresenceKind.BED, PresenceKind.SEAT,
            PresenceKind.FLUSH, PresenceKind.APPLIANCE);

    private PresenceNodeKind() {
    }

    /** @return the node type name of a kind, e.g. {@code presence-seat} for SEAT */
    static String typeName(PresenceKind kind) {
        return NodeType.PRESENCE_PREFIX + kind.name().toLowerCase(Locale.ROOT);
    }

    /**
     * @param nodeTypes the bus device's node types
     * @return the first presence kind announced (bed, seat, flush, appliance), OTHER if none is (the driver only
     *         creates devices for nodes with one, so OTHER means the node changed its types since)
     */
    static PresenceKind of(Set<String> nodeTypes) {
        return ORDER.stream().filter(k -> nodeTypes.contains(typeName(k))).findFirst().orElse(PresenceKind.OTHER);
    }

    /** @return the default device name, e.g. {@code Seat mat 1.41} */
    static String defaultName(PresenceKind kind, String node) {
        String what = switch (kind) {
            case BED -> "Bed mat";
            case SEAT -> "Seat mat";
            case FLUSH -> "Flush";
            case APPLIANCE -> "Appliance";
            case OTHER -> "Presence";
        };
        return what + " " + node;
    }
}

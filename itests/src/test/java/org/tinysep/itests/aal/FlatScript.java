package org.tinysep.itests.aal;

import java.io.IOException;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.tinysep.itests.AmicaNode;

/** A script of sensor events for {@link VirtualFlat#play}, written as a readable table in the test. */
final class FlatScript {

    private FlatScript() {
    }

    /** How a node sends one event's frame. */
    @FunctionalInterface
    interface SensorFrame {
        void send(AmicaNode node) throws IOException;
    }

    /** One line of a script: at this virtual time, this node sends this frame. */
    record Event(Instant at, AmicaNode node, SensorFrame frame, String text) {
    }

    /**
     * Parses a script table, one event a line: {@code HH:mm:ss motion <Room>}, {@code HH:mm:ss pet},
     * {@code HH:mm:ss door open|closed}; anything after {@code --} is a comment.
     */
    static List<Event> parse(VirtualFlat flat, String table, Map<String, AmicaNode> motionSensors, AmicaNode door, AmicaNode collar) {
        List<Event> events = new ArrayList<>();
        for (String raw : table.split("\n")) {
            String line = raw.split("--")[0].trim();
            if (line.isEmpty()) {
                continue;
            }
            String[] w = line.split("\\s+", 3);
            Instant at = flat.at(w[0]);
            switch (w[1]) {
            case "motion" -> events.add(new Event(at, require(motionSensors.get(w[2]), line), n -> n.motion(true), line));
            case "pet" -> events.add(new Event(at, require(collar, line), n -> n.motion(true), line));
            case "door" -> {
                boolean open = switch (w[2]) {
                case "open" -> true;
                case "closed" -> false;
                default -> throw new IllegalArgumentException("door open|closed expected: " + line);
                };
                events.add(new Event(at, require(door, line), n -> VirtualFlat.door(n, open), line));
            }
            default -> throw new IllegalArgumentException("unknown event: " + line);
            }
        }
        return events;
    }

    private static AmicaNode require(AmicaNode node, String line) {
        if (node == null) {
            throw new IllegalArgumentException("no such sensor: " + line);
        }
        return node;
    }
}

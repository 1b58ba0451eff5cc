package org.tinysep.simulator.flat;

import java.util.List;
import java.util.Map;

/**
 * One line of a node layout: a node's id, family, address ({@code NG.ADDR} or {@code 0014.4F01.0000.XXXX}), node
 * type names, room and options ({@code door=outer|inner}, {@code agent=<pet>}, {@code percent=<initial value>}).
 */
public record NodeSpec(String id, Family family, String address, List<String> types, String room,
        Map<String, String> options) {

    public NodeSpec {
        types = List.copyOf(types);
        options = Map.copyOf(options);
    }

    public boolean has(String type) {
        return types.contains(type);
    }

    /** @return true for a door node whose {@code door} option is {@code outer} (the flat's entrance) */
    public boolean outerDoor() {
        return has("door") && "outer".equals(options.get("door"));
    }

    /** @return the agent carrying this node (a pet collar, a worn person node), or null when it is fixed in its room */
    public String carriedBy() {
        return options.get("agent");
    }

    public int initialPercent() {
        return Integer.parseInt(options.getOrDefault("percent", "0"));
    }
}

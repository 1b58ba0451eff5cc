package org.tinysep.simulator.flat;

import java.util.List;
import java.util.Optional;

/** A simulated flat: its house plan and its node layout. */
public record Flat(String name, House house, List<NodeSpec> nodes) {

    public Flat {
        nodes = List.copyOf(nodes);
    }

    /** @return the flat without its worn person nodes (a day without the pendant: the room sensors only) */
    public Flat withoutPersonNodes() {
        return new Flat(name, house, nodes.stream().filter(n -> !n.has("person")).toList());
    }

    /** @return the room of the flat's outer door (where people leave and arrive), if it has one */
    public Optional<String> entrance() {
        return nodes.stream().filter(NodeSpec::outerDoor).map(NodeSpec::room).findFirst();
    }
}

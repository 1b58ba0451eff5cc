package org.tinysep.device.support.health;

import java.time.Duration;
import java.util.Map;
import java.util.Set;
import org.tinysep.api.device.NodeType;

/**
 * The report periods the thesis's node types promise (3.9.1 AmICA, 3.9.2 Sun SPOT): a movement or pet collar node
 * reports every 2 s, a reed switch (door, window) and a presence node (a mat, flush or appliance sending
 * Reed-Switch Status) every second, lights, heaters, speakers and the Sun SPOT
 * temperature and light sensors every 10 s, a person node sends its movement summary every 2 s. Used to tell a
 * silent node (sensor health) and to rate its link.
 */
public final class ReportRates {

    private static final Map<String, Integer> PERIOD_SECONDS = Map.ofEntries(
            Map.entry(NodeType.MOVEMENT, 2), Map.entry(NodeType.PET_COLLAR, 2), Map.entry(NodeType.DOOR, 1),
            Map.entry(NodeType.WINDOW, 1), Map.entry(NodeType.SIMPLE_LIGHT, 10), Map.entry(NodeType.DIMMABLE_LIGHT, 10),
            Map.entry(NodeType.HEATER, 10), Map.entry(NodeType.SPEAKER, 10), Map.entry(NodeType.TEMPERATURE, 10),
            Map.entry(NodeType.LIGHT_SENSOR, 10), Map.entry(NodeType.PERSON, 2));

    private ReportRates() {
    }

    /**
     * @param fallback the interval for a node of no known type (an AmICA node's keep-alive period)
     * @return the shortest report period of the types: how often the node is heard at least
     */
    public static Duration interval(Set<String> nodeTypes, Duration fallback) {
        return nodeTypes.stream().map(ReportRates::period).filter(p -> p != null).min(Integer::compare)
                .map(Duration::ofSeconds).orElse(fallback);
    }

    /** @return reports per second the types promise together (a node of several types sends each report) */
    public static double perSecond(Set<String> nodeTypes) {
        return nodeTypes.stream().map(ReportRates::period).filter(p -> p != null).mapToDouble(p -> 1.0 / p).sum();
    }

    /** @return the report period of one node type in seconds, null if unknown */
    private static Integer period(String nodeType) {
        return nodeType.startsWith(NodeType.PRESENCE_PREFIX) ? Integer.valueOf(1) : PERIOD_SECONDS.get(nodeType);
    }
}

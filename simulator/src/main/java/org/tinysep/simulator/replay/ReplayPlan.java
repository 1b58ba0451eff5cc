package org.tinysep.simulator.replay;

import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.tinysep.amica.protocol.AmicaAddress;

/**
 * What the simulator must do to replay a recording: the nodes to create ({@link #nodes()}) and, in time order, the
 * state each node enters when ({@link #actions()}). A node keeps reporting its last state at its protocol rate
 * (thesis 3.9: movement every 2 s, reed switch every 1 s) until its next action; that, keep-alives and the mapping of
 * recorded time onto virtual time are the simulator core's job.
 *
 * @param nodes   one node per recorded sensor, in order of the sensor's first event
 * @param actions one action per event, time-ordered (stable)
 */
public record ReplayPlan(List<NodeSpec> nodes, List<NodeAction> actions) {

    /** Copies the lists. */
    public ReplayPlan {
        nodes = List.copyOf(nodes);
        actions = List.copyOf(actions);
    }

    /**
     * @param events  recorded events (sorted here, stably, by time)
     * @param mapping the mapping file; sensors it does not name get default types and allocated addresses
     * @return the plan
     * @throws IllegalArgumentException if a sensor's node is invalid (e.g. doorKind on a non-door), if one sensor is
     *                                  recorded with two different kinds, or if the netgroup runs out of addresses
     */
    public static ReplayPlan of(List<SensorEvent> events, SensorMapping mapping) {
        List<SensorEvent> sorted = new ArrayList<>(events);
        sorted.sort(Comparator.comparing(SensorEvent::time));
        Set<AmicaAddress> used = new HashSet<>(mapping.explicitAddresses());
        AmicaAddress next = mapping.firstFree();
        Map<String, NodeSpec> nodes = new LinkedHashMap<>();
        Map<String, Kind> kinds = new LinkedHashMap<>();
        List<NodeAction> actions = new ArrayList<>(sorted.size());
        for (SensorEvent e : sorted) {
            Kind known = kinds.putIfAbsent(e.sensor(), e.kind());
            if (known != null && known != e.kind()) {
                throw new IllegalArgumentException("sensor '" + e.sensor() + "' is recorded as " + known.csvName()
                        + " and as " + e.kind().csvName());
            }
            NodeSpec node = nodes.get(e.sensor());
            if (node == null) {
                AmicaAddress address = null;
                if (mapping.needsAddress(e.sensor())) {
                    next = free(next, used);
                    address = next;
                    used.add(address);
                }
                node = mapping.resolve(e.sensor(), e.room(), e.kind(), address);
                nodes.put(e.sensor(), node);
            }
            actions.add(new NodeAction(e.time(), node, Signal.of(node.isMotion(), e.on())));
        }
        return new ReplayPlan(new ArrayList<>(nodes.values()), actions);
    }

    /** @return the time of the first action, or null if the plan is empty */
    public LocalDateTime start() {
        return actions.isEmpty() ? null : actions.get(0).time();
    }

    /** @return the time of the last action, or null if the plan is empty */
    public LocalDateTime end() {
        return actions.isEmpty() ? null : actions.get(actions.size() - 1).time();
    }

    /**
     * @param action an action of this plan
     * @return how long after {@link #start()} it happens: add this to the simulation's start in virtual time
     */
    public java.time.Duration offsetOf(NodeAction action) {
        return java.time.Duration.between(start(), action.time());
    }

    private static AmicaAddress free(AmicaAddress from, Set<AmicaAddress> used) {
        for (int a = from.address(); a <= 255; a++) {
            AmicaAddress candidate = new AmicaAddress(from.netgroup(), a);
            if (!used.contains(candidate)) {
                return candidate;
            }
        }
        throw new IllegalArgumentException("no free address left in netgroup " + from.netgroup()
                + " from " + from + "; give the sensors explicit 'node = amica NG.ADDR' entries or another 'allocate'");
    }
}

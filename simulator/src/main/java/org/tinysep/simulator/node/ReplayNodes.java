package org.tinysep.simulator.node;

import java.io.Closeable;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tinysep.simulator.replay.NodeSpec;

/** The nodes of a replay: one {@link ReplayNode} with its own UDP socket per recorded sensor. */
public final class ReplayNodes implements AutoCloseable {

    private final Map<String, ReplayNode> bySensor = new LinkedHashMap<>();
    private final NodeSet set;

    private ReplayNodes(List<ReplayNode> nodes, List<Closeable> resources) {
        nodes.forEach(n -> bySensor.put(n.recorded().sensor(), n));
        this.set = new NodeSet(new ArrayList<>(nodes), resources);
    }

    /**
     * @param specs    the replay plan's nodes
     * @param target   where the platform's bus radio listens
     * @param fullRate true: repeat the current state at the protocol rate; false: send changes and keep-alives only
     */
    public static ReplayNodes create(List<NodeSpec> specs, Target target, boolean fullRate) throws IOException {
        List<Closeable> resources = new ArrayList<>();
        List<ReplayNode> nodes = new ArrayList<>();
        try {
            for (NodeSpec s : specs) {
                AmicaPort port = new AmicaPort(s.address(), target);
                resources.add(port::close);
                nodes.add(new ReplayNode(s, port, fullRate));
            }
        } catch (IOException | RuntimeException e) {
            new NodeSet(new ArrayList<>(nodes), resources).close();
            throw e;
        }
        return new ReplayNodes(nodes, resources);
    }

    /** @return the node replaying {@code sensor} */
    public ReplayNode node(String sensor) {
        ReplayNode n = bySensor.get(sensor);
        if (n == null) {
            throw new IllegalArgumentException("no replay node for sensor '" + sensor + "'");
        }
        return n;
    }

    /** Sends the periodic reports and keep-alives due at virtual second {@code t}. */
    public void tick(long t) {
        set.tick(t);
    }

    public List<ReplayNode> nodes() {
        return List.copyOf(bySensor.values());
    }

    @Override
    public void close() {
        set.close();
    }
}

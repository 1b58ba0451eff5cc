package org.tinysep.simulator.node;

import java.io.Closeable;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntSupplier;

/** All nodes of a simulated flat: ticked together, switched by id, closed together. */
public final class NodeSet implements AutoCloseable {

    private final Map<String, SimNode> nodes = new LinkedHashMap<>();
    private final List<Closeable> resources;
    private final IntSupplier beforeTick;

    NodeSet(List<SimNode> nodes, List<Closeable> resources) {
        this(nodes, resources, () -> 0);
    }

    /**
     * @param beforeTick runs at the start of every {@link #tick}: commands waiting for the nodes are carried out;
     *                   returns how many answers report a changed value
     */
    NodeSet(List<SimNode> nodes, List<Closeable> resources, IntSupplier beforeTick) {
        nodes.forEach(n -> this.nodes.put(n.spec().id(), n));
        this.resources = resources;
        this.beforeTick = beforeTick;
    }

    public List<SimNode> nodes() {
        return List.copyOf(nodes.values());
    }

    public SimNode node(String id) {
        return nodes.get(id);
    }

    /** @return how many reported values changed (see {@link SimNode#tick}), command answers included */
    public int tick(long t) {
        int changed = beforeTick.getAsInt();
        for (SimNode n : nodes.values()) {
            changed += n.tick(t);
        }
        return changed;
    }

    /** @return the instants inside second {@code t} at which a powered node has a frame due, in order, once each */
    public List<java.time.Instant> dueWithin(long t) {
        java.util.TreeSet<java.time.Instant> due = new java.util.TreeSet<>();
        for (SimNode n : nodes.values()) {
            if (n.powered()) {
                due.addAll(n.dueWithin(t));
            }
        }
        return List.copyOf(due);
    }

    /** Sends what the nodes have due by {@code at}. @return as {@link #tick} */
    public int sendDue(java.time.Instant at) {
        int changed = 0;
        for (SimNode n : nodes.values()) {
            if (n.powered()) {
                changed += n.sendDue(at);
            }
        }
        return changed;
    }

    /** Switches a node's battery on or off; unknown ids are reported, never thrown. */
    public void power(String id, boolean on) {
        SimNode n = nodes.get(id);
        if (n == null) {
            NodeLog.LOG.warning("no node '" + id + "' to switch " + (on ? "on" : "off"));
            return;
        }
        n.power(on);
    }

    @Override
    public void close() {
        for (Closeable c : resources) {
            try {
                c.close();
            } catch (IOException e) {
                NodeLog.LOG.fine("closing: " + e);
            }
        }
    }
}

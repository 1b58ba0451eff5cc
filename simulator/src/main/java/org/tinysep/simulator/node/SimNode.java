package org.tinysep.simulator.node;

import org.tinysep.simulator.flat.NodeSpec;

/**
 * A simulated node: sends its reports when due, once per virtual second, and can be switched off (battery
 * empty: silent, commands ignored) and on again (it starts up anew: uptime 0, keep-alive first).
 */
public abstract class SimNode {

    protected final NodeSpec spec;
    private volatile boolean powered = true;
    private volatile boolean booting = true;
    private long bootSecond;

    protected SimNode(NodeSpec spec) {
        this.spec = spec;
    }

    public NodeSpec spec() {
        return spec;
    }

    public boolean powered() {
        return powered;
    }

    public void power(boolean on) {
        if (on && !powered) {
            booting = true;
        }
        powered = on;
    }

    /**
     * Sends the reports due at virtual second {@code t}.
     *
     * @return how many of them report a value different from the node's previous report of that kind
     */
    public final int tick(long t) {
        if (!powered) {
            return 0;
        }
        if (booting) {
            booting = false;
            bootSecond = t;
        }
        return report(t, t - bootSecond);
    }

    protected abstract int report(long t, long elapsed);

    /**
     * @return the instants after second {@code t} and before the next at which this node has a frame to send, in
     *         order (a worn node's burst leaves at its trigger); none by default
     */
    public java.util.List<java.time.Instant> dueWithin(long t) {
        return java.util.List.of();
    }

    /** Sends what is due by {@code at}, one of {@link #dueWithin}'s instants. @return as {@link #tick} */
    public int sendDue(java.time.Instant at) {
        return 0;
    }
}

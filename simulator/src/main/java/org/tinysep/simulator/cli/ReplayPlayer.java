package org.tinysep.simulator.cli;

import java.util.List;
import org.tinysep.simulator.node.ReplayNodes;
import org.tinysep.simulator.replay.NodeAction;

/**
 * Plays a {@link Replay} one virtual second at a time: the nodes' due keep-alives and periodic reports first, then
 * every recorded action of that second in file order, each reported at once. {@link #next} tells a lock-step driver
 * which second is the next one with something to send, so quiet stretches cost one tick per {@code maxStep}.
 */
final class ReplayPlayer {

    private final Replay replay;
    private final ReplayNodes nodes;
    private final List<NodeAction> actions;
    private final long grid;
    private final int maxStep;
    private int nextAction;
    private int sent;

    /**
     * @param maxStep the longest stretch between two played seconds (1 at the full rate: every second has reports;
     *                a divisor of the keep-alive period otherwise, so keep-alives stay on time)
     */
    ReplayPlayer(Replay replay, ReplayNodes nodes, int maxStep) {
        this.replay = replay;
        this.nodes = nodes;
        this.actions = replay.plan().actions();
        this.grid = replay.fromSecond();
        this.maxStep = maxStep;
    }

    /** Plays second {@code t}. @return how many nodes changed state */
    int step(long t) {
        nodes.tick(t);
        int changed = 0;
        while (nextAction < actions.size() && replay.virtualSecond(actions.get(nextAction).time()) <= t) {
            NodeAction a = actions.get(nextAction++);
            changed += nodes.node(a.node().sensor()).enter(a.signal());
            sent++;
        }
        return changed;
    }

    /** @return the next second to play after {@code t}: the next grid second or the next action's, if sooner */
    long next(long t) {
        long onGrid = grid + ((t - grid) / maxStep + 1) * maxStep;
        if (nextAction < actions.size()) {
            return Math.min(onGrid, Math.max(t + 1, replay.virtualSecond(actions.get(nextAction).time())));
        }
        return onGrid;
    }

    /** @return recorded actions sent so far */
    int sent() {
        return sent;
    }
}

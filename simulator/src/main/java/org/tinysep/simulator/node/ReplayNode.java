package org.tinysep.simulator.node;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.tinysep.amica.protocol.AmicaAddress;
import org.tinysep.amica.protocol.AmicaNodeType;
import org.tinysep.simulator.flat.Family;
import org.tinysep.simulator.flat.NodeSpec;
import org.tinysep.simulator.replay.Signal;

/**
 * An AmICA node that replays a recorded sensor: it enters each recorded state when told ({@link #enter}) and
 * reports it at once — a zero-length interval still sends its ON and its OFF, in order — and, at the full rate,
 * repeats its current state at its protocol rate (thesis 3.9: motion every 2 s, reed switch every 1 s). Keep-alives
 * every {@link Rates#KEEP_ALIVE} s; the first one at start-up, before any other frame.
 */
public final class ReplayNode extends SimNode {

    private final org.tinysep.simulator.replay.NodeSpec recorded;
    private final AmicaPort port;
    private final boolean fullRate;
    private final int productId;
    private final long serial;
    private Signal state;

    ReplayNode(org.tinysep.simulator.replay.NodeSpec recorded, AmicaPort port, boolean fullRate) {
        super(layoutOf(recorded));
        this.recorded = recorded;
        this.port = port;
        this.fullRate = fullRate;
        this.productId = AmicaNodeType.productId(List.of(recorded.type()));
        AmicaAddress a = recorded.address();
        this.serial = 0x5200_0000L + a.netgroup() * 256L + a.address();
        this.state = recorded.isMotion() ? Signal.MOTION_OFF : Signal.CONTACT_CLOSED;
    }

    /** @return the recorded sensor's node */
    public org.tinysep.simulator.replay.NodeSpec recorded() {
        return recorded;
    }

    /** @return the state the node reports now */
    public synchronized Signal state() {
        return state;
    }

    /**
     * Enters a recorded state and reports it at once (if switched on).
     *
     * @return 1 if the state changed, else 0
     */
    public synchronized int enter(Signal signal) {
        int changed = signal == state ? 0 : 1;
        state = signal;
        if (powered()) {
            port.send(signal.payload());
        }
        return changed;
    }

    @Override
    protected synchronized int report(long t, long elapsed) {
        if (Rates.due(elapsed, Rates.KEEP_ALIVE)) {
            port.sendKeepAlive(elapsed, productId, serial);
        }
        if (fullRate && Rates.due(elapsed, recorded.isMotion() ? Rates.MOTION : Rates.REED_SWITCH)) {
            port.send(state.payload());
        }
        return 0;
    }

    /** @return the seconds between two periodic reports at the full rate */
    public int period() {
        return recorded.isMotion() ? Rates.MOTION : Rates.REED_SWITCH;
    }

    private static NodeSpec layoutOf(org.tinysep.simulator.replay.NodeSpec r) {
        Map<String, String> options = r.type() == AmicaNodeType.DOOR
                ? Map.of("door", r.doorKind().toLowerCase(Locale.ROOT)) : Map.of();
        return new NodeSpec(r.sensor(), Family.AMICA, r.address().toString(), List.of(r.type().typeName()),
                r.room(), options);
    }
}

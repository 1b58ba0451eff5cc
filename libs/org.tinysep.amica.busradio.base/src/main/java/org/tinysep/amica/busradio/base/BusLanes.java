package org.tinysep.amica.busradio.base;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.device.support.delivery.GuardedLane;
import org.tinysep.device.support.delivery.OrderedDelivery;

/**
 * The listeners of one bus device and the way its payloads reach them: through the radio's {@link OrderedDelivery}
 * (one ordered queue for all its devices), or on the receive thread when the radio has none. The
 * {@link Handover}'s monitor orders the choice of listeners for a payload against listeners connecting and
 * leaving; no listener is ever called while it is held (a slow one must not hold the next payload's choice).
 * A payload is given to a leaving listener or held for its replacement, never neither, in order.
 */
final class BusLanes {

    private static final Logger LOG = LoggerFactory.getLogger(BusLanes.class);

    private final BusRadioAmicaProvider source;
    private final String node;
    final Handover handover = new Handover(System::nanoTime);
    private volatile List<Lane> lanes = List.of(); // replaced whole, under the handover's monitor
    private volatile OrderedDelivery delivery;
    private long connects; // guarded by handover

    /** @param node the node in words, e.g. "AmICA node 1.17" */
    BusLanes(BusRadioAmicaProvider source, String node) {
        this.source = source;
        this.node = node;
    }

    void delivery(OrderedDelivery d) {
        this.delivery = d;
    }

    /** On the receive thread: queues the payload for the listeners (or gives it to them now, without a dispatcher). */
    void received(byte[] payload, Instant at) {
        PayloadJob job = new PayloadJob(new Handover.Held(payload, at));
        OrderedDelivery d = delivery;
        if (d == null) {
            OrderedDelivery.inline(job);
        } else {
            d.submit(job);
        }
    }

    /** Connects a listener; a replacement first gets what was held since its predecessor left, in order. */
    Connection connect(BusRadioAmicaListener listener) {
        synchronized (handover) {
            Lane lane = new Lane(listener, ++connects);
            List<Lane> more = new ArrayList<>(lanes);
            more.add(lane);
            lanes = List.copyOf(more);
            for (Handover.Held h : handover.claim()) {
                try {
                    listener.payloadReceived(source, h.payload().clone(), h.at());
                } catch (RuntimeException e) {
                    LOG.warn("Listener {} of {} failed on a replayed payload: {}", listener.getClass().getName(),
                            node, e.toString());
                }
            }
            return lane;
        }
    }

    /** @return whether devices depend on the node: listeners connected, or one left and its replacement is due */
    boolean dependedOn() {
        if (!lanes.isEmpty()) {
            return true;
        }
        synchronized (handover) {
            return handover.awaitingReplacement();
        }
    }

    List<BusRadioAmicaListener> connected() {
        return lanes.stream().map(l -> l.listener).toList();
    }

    /** The bus device goes: every listener is disconnected, nothing is held. */
    void closeAll() {
        synchronized (handover) {
            lanes.forEach(Lane::disconnect);
            lanes = List.of();
        }
    }

    private final class PayloadJob extends OrderedDelivery.Job<Handover.Held> {
        private boolean recorded; // held for a replacement when the dispatcher took it
        private long seq; // the last listener connected then

        PayloadJob(Handover.Held item) {
            super(item);
        }

        @Override
        protected List<Lane> begin() {
            synchronized (handover) {
                recorded = handover.record(item().payload(), item().at());
                seq = connects;
                return lanes;
            }
        }

        @Override
        protected List<Lane> missed(GuardedLane<Handover.Held> lane) {
            synchronized (handover) {
                if (recorded) {
                    return List.of(); // its replacement gets it from the handover
                }
                if (handover.awaitingReplacement()) {
                    handover.hold(item());
                    return List.of();
                }
                return lanes.stream().filter(l -> l.seq > seq).toList(); // the replacement came already
            }
        }
    }

    private final class Lane extends GuardedLane<Handover.Held> implements Connection {
        final BusRadioAmicaListener listener;
        final long seq;

        Lane(BusRadioAmicaListener listener, long seq) {
            this.listener = listener;
            this.seq = seq;
        }

        @Override
        protected void call(Handover.Held h) {
            listener.payloadReceived(source, h.payload().clone(), h.at());
        }

        @Override
        protected String describe() {
            return listenerWords(listener, node);
        }

        /** The listener leaves: what was queued for it and not yet given is held for its replacement, first. */
        @Override
        public void close() {
            synchronized (handover) {
                if (isClosed()) {
                    return;
                }
                List<Handover.Held> undelivered = new ArrayList<>();
                for (OrderedDelivery.Job<Handover.Held> j : shut()) {
                    if (!((PayloadJob) j).recorded) {
                        undelivered.add(j.item());
                    }
                }
                List<Lane> rest = new ArrayList<>(lanes);
                rest.remove(this);
                lanes = List.copyOf(rest);
                handover.listenerLeft(undelivered);
            }
        }

        @Override
        public boolean isOpen() {
            return !isClosed();
        }

        /** The bus device goes: nothing more for this listener, nothing held. */
        void disconnect() {
            shut();
        }
    }
}

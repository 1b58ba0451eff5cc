package org.tinysep.sunspot.busradio.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.device.support.delivery.GuardedLane;
import org.tinysep.device.support.delivery.OrderedDelivery;

/**
 * The listeners of one Sun SPOT bus device and the way its packets reach them: through the radio's
 * {@link OrderedDelivery} (one ordered queue for all its devices, a slow listener taken out of the ordered path so
 * it never stalls a link's receive thread or the other devices), or on the caller's thread when the radio has none
 * (tests). Each listener gets its own copy of the payload. A listener that leaves gets nothing more.
 */
final class SunSpotLanes {

    /** One valid packet for the listeners. */
    record Packet(int sensorType, byte[] payload, Instant at) {
    }

    private final BusRadioSunSpotProvider source;
    private final String node;
    private volatile List<Lane> lanes = List.of(); // replaced whole, under this

    /** @param node the node in words, e.g. "Sun SPOT 0014.4F01.0000.1234" */
    SunSpotLanes(BusRadioSunSpotProvider source, String node) {
        this.source = source;
        this.node = node;
    }

    /** On a link's receive thread: queues the packet for the listeners (or gives it to them now, without one). */
    void received(OrderedDelivery delivery, int sensorType, byte[] payload, Instant at) {
        PacketJob job = new PacketJob(new Packet(sensorType, payload, at), lanes); // the listeners connected now
        if (delivery == null) {
            OrderedDelivery.inline(job);
        } else {
            delivery.submit(job);
        }
    }

    synchronized Connection connect(BusRadioSunSpotListener listener) {
        if (listener == null) {
            throw new IllegalArgumentException("listener must not be null");
        }
        Lane lane = new Lane(listener);
        List<Lane> more = new ArrayList<>(lanes);
        more.add(lane);
        lanes = List.copyOf(more);
        return lane;
    }

    /** The bus device goes: every listener is disconnected. */
    synchronized void closeAll() {
        lanes.forEach(Lane::disconnect);
        lanes = List.of();
    }

    private synchronized void leave(Lane lane) {
        List<Lane> rest = new ArrayList<>(lanes);
        rest.remove(lane);
        lanes = List.copyOf(rest);
    }

    /**
     * A packet for the listeners connected when it was received (as on the receive thread before the ordered
     * queue): one that connects while the packet waits in the queue does not get it, so "packets" (counted when
     * handed on) and what a listener connected after that count hears agree.
     */
    private static final class PacketJob extends OrderedDelivery.Job<Packet> {
        private final List<Lane> targets;

        PacketJob(Packet item, List<Lane> targets) {
            super(item);
            this.targets = targets;
        }

        @Override
        protected List<Lane> begin() {
            return targets;
        }

        @Override
        protected List<Lane> missed(GuardedLane<Packet> lane) {
            return List.of(); // the listener left: it gets nothing more
        }
    }

    private final class Lane extends GuardedLane<Packet> implements Connection {
        final BusRadioSunSpotListener listener;

        Lane(BusRadioSunSpotListener listener) {
            this.listener = listener;
        }

        @Override
        protected void call(Packet p) {
            listener.payloadReceived(source, p.sensorType(), p.payload().clone(), p.at());
        }

        @Override
        protected String describe() {
            return listenerWords(listener, node);
        }

        @Override
        public void close() {
            if (!isClosed()) {
                shut();
                leave(this);
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

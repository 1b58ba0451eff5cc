package org.tinysep.mqtt.internal;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * What waits to be published, in the order it goes out: alert messages (on disk, by seq, never dropped), then
 * command results (at most {@link #MAX_TRANSIENT}, the oldest dropped and counted beyond), then state (one pending
 * message per topic: a newer value replaces an unsent older one). At most {@link #WINDOW} messages are in flight
 * (published, PUBACK not yet received). Used only on the bridge's own thread.
 */
final class Outbox {

    static final int WINDOW = 16;
    static final int MAX_TRANSIENT = 1000;

    private final AlertSpool spool;
    private final Map<String, Message> current = new LinkedHashMap<>();
    private final Set<String> pendingState = new LinkedHashSet<>();
    private final ArrayDeque<Message> transients = new ArrayDeque<>();
    private final Set<Long> spoolInFlight = new HashSet<>();
    private int inFlight;
    private long droppedTransient;
    private long coalesced;
    private long delivered;
    private boolean resync;

    private final String firstTopic;

    /** @param firstTopic the state topic sent before anything else after a connection ({@code P/F/status}) */
    Outbox(AlertSpool spool, String firstTopic) {
        this.spool = spool;
        this.firstTopic = firstTopic;
    }

    AlertSpool spool() {
        return spool;
    }

    /** A retained state message: published unless the same payload is already published or waiting. */
    void state(Message m) {
        Message before = current.get(m.topic());
        if (m.samePayload(before)) {
            return;
        }
        current.put(m.topic(), m);
        if (!pendingState.add(m.topic())) {
            coalesced++;
        }
    }

    /** Forgets a state topic (a device removed); nothing is published for it. */
    void forget(String topic) {
        current.remove(topic);
        pendingState.remove(topic);
    }

    void transientMessage(Message m) {
        if (transients.size() >= MAX_TRANSIENT) {
            transients.removeFirst();
            droppedTransient++;
        }
        transients.addLast(m);
    }

    /** Keeps an alert message on disk until the broker acknowledges it. */
    void alert(Message m) throws IOException {
        spool.add(m);
    }

    /** A new connection: every state topic and every delivered alert is published again (retained). */
    void connected() {
        inFlight = 0;
        spoolInFlight.clear();
        pendingState.addAll(current.keySet());
        resync = true;
    }

    /** @return the next messages to publish now, at most what the window allows */
    List<Message> next() {
        List<Message> out = new ArrayList<>();
        if (pendingState.remove(firstTopic)) {
            out.add(current.get(firstTopic));
        }
        if (resync) {
            resync = false;
            out.addAll(spool.delivered());
        }
        for (Message m : spool.pending()) {
            if (inFlight + out.size() >= WINDOW) {
                break;
            }
            if (spoolInFlight.add(m.key())) {
                out.add(m);
            }
        }
        while (inFlight + out.size() < WINDOW && !transients.isEmpty()) {
            out.add(transients.removeFirst());
        }
        var it = pendingState.iterator();
        while (inFlight + out.size() < WINDOW && it.hasNext()) {
            out.add(current.get(it.next()));
            it.remove();
        }
        inFlight += out.size();
        return out;
    }

    /** The broker acknowledged {@code m} (or, for a state message, it failed and a reconnection republishes it). */
    void done(Message m, boolean ok) throws IOException {
        inFlight = Math.max(0, inFlight - 1);
        if (m.spooled()) {
            spoolInFlight.remove(m.key());
            if (ok) {
                spool.delivered(m);
            }
        }
        if (ok) {
            delivered++;
        } else if (!m.spooled() && m.retained() && current.get(m.topic()) == m) {
            pendingState.add(m.topic());
        }
    }

    int waitingAlerts() {
        return spool.size();
    }

    int waitingState() {
        return pendingState.size();
    }

    long droppedTransient() {
        return droppedTransient;
    }

    long coalesced() {
        return coalesced;
    }

    long delivered() {
        return delivered;
    }
}

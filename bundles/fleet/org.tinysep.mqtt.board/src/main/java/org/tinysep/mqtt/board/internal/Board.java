package org.tinysep.mqtt.board.internal;

import java.time.Instant;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.json.JsonSignature;

/**
 * The board's state machine: takes every message of the subscribed topics and keeps one {@link Flat} per flat.
 * Never throws for a message: a payload that breaks the contract is counted (per flat and in total) with its
 * reason, a duplicate or stale alert (by {@code seq}) is counted and dropped. At most {@code maxFlats} flats.
 */
final class Board {

    private final String prefix;
    private final int maxFlats;
    private final Map<String, Flat> flats = new ConcurrentHashMap<>();
    private final AtomicLong messages = new AtomicLong();
    private final AtomicLong bad = new AtomicLong();
    private final AtomicLong duplicates = new AtomicLong();
    private final AtomicLong refusedFlats = new AtomicLong();
    private final AtomicLong unknownFlats = new AtomicLong();
    private final AtomicLong unsigned = new AtomicLong();
    private final FlatKeys keys;

    /** A board of the state machine alone: every flat, no signature checked (the tests of the rules). */
    Board(String prefix, int maxFlats) {
        this(prefix, maxFlats, null);
    }

    /**
     * @param keys the flats followed and their keys: messages of other flats are ignored, and each message of a
     *             flat must be signed with its key (docs/central-board.md, "Security"); null = no check
     */
    Board(String prefix, int maxFlats, FlatKeys keys) {
        this.prefix = prefix;
        this.maxFlats = maxFlats;
        this.keys = keys;
    }

    /**
     * Counters over all flats, for the page and the load test.
     *
     * @param unknownFlats messages of flats the board has no key for, ignored
     * @param unsigned     messages of known flats not signed (or badly) with their key, or empty alerts: ignored
     */
    record Totals(long messages, long bad, long duplicates, long refusedFlats, int flats, long unknownFlats,
            long unsigned) { }

    /**
     * Applies one message.
     *
     * @return true when it changed what the board shows
     */
    boolean accept(String topic, byte[] payload, Instant at) {
        messages.incrementAndGet();
        Optional<Topic> parsed = Topic.parse(prefix, topic);
        if (parsed.isEmpty()) {
            bad.incrementAndGet();
            return false;
        }
        Topic t = parsed.get();
        byte[] key = keys == null ? null : keys.of(t.flat());
        if (keys != null && key == null) {
            unknownFlats.incrementAndGet(); // a flat this board has no key for: never shown (no fake flats)
            return false;
        }
        Flat flat = flat(t.flat(), at);
        if (flat == null) {
            return false;
        }
        try {
            String text = Payloads.text(payload);
            if (key != null && t.kind() != Topic.Kind.STATUS) {
                text = signed(flat, t.flat(), topic, text, key, at);
                if (text == null) {
                    return false;
                }
            }
            return apply(flat, t, text, at);
        } catch (IllegalArgumentException e) {
            bad.incrementAndGet();
            flat.bad(topic, e.getMessage(), at);
            return false;
        }
    }

    /**
     * @return the message without its signature, null when it is ignored: empty (a retained alert or health being
     *         emptied cannot be signed; the flat's signed CLEARED ends an alert) or not signed with the flat's key
     */
    private String signed(Flat flat, String flatId, String topic, String text, byte[] key, Instant at) {
        if (text.isEmpty()) {
            unsigned.incrementAndGet();
            return null;
        }
        JsonSignature.Checked c = JsonSignature.check(key, topic, text);
        if (!c.valid()) {
            unsigned.incrementAndGet();
            flat.bad(topic, (c.signed() ? "wrong signature" : "not signed") + ": not sent with flat "
                    + flatId + "'s key, ignored (a fake or a bridge with another key)", at);
            return null;
        }
        return c.unsigned();
    }

    private boolean apply(Flat flat, Topic t, String text, Instant at) {
        boolean empty = text.isEmpty(); // a retained topic being emptied
        switch (t.kind()) {
            case STATUS -> flat.status(empty ? null : Payloads.status(text), at);
            case PLATFORM -> {
                if (!empty) {
                    flat.platform(Payloads.platform(Payloads.fields(text)), at);
                }
            }
            case SUMMARY -> {
                if (!empty) {
                    flat.summary(Payloads.summary(Payloads.fields(text)), at);
                }
            }
            case OCCUPANCY -> {
                if (!empty) {
                    flat.occupancy(Payloads.occupancy(Payloads.fields(text)), at);
                }
            }
            case HEALTH -> flat.health(t.id(), empty ? null : Payloads.health(Payloads.fields(text)), at);
            case ALERT -> {
                if (empty) {
                    flat.alertGone(t.id(), at);
                } else if (!flat.alert(Payloads.alert(t.flat(), t.id(), Payloads.fields(text)), at)) {
                    duplicates.incrementAndGet();
                    return false;
                }
            }
            default -> throw new IllegalStateException("unhandled " + t.kind());
        }
        return true;
    }

    /** @return the flat, created on its first message; null when the board already tracks {@code maxFlats} */
    Flat flat(String id, Instant at) {
        Flat f = flats.get(id);
        if (f != null) {
            return f;
        }
        if (flats.size() >= maxFlats) {
            refusedFlats.incrementAndGet();
            return null;
        }
        return flats.computeIfAbsent(id, k -> new Flat(k, at));
    }

    Optional<Flat> find(String id) {
        return Optional.ofNullable(flats.get(id));
    }

    Collection<Flat> flats() {
        return List.copyOf(flats.values());
    }

    Totals totals() {
        return new Totals(messages.get(), bad.get(), duplicates.get(), refusedFlats.get(), flats.size(),
                unknownFlats.get(), unsigned.get());
    }

    String prefix() {
        return prefix;
    }
}

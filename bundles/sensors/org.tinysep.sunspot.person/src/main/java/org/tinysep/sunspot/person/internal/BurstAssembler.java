package org.tinysep.sunspot.person.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.sunspot.protocol.BurstChunk;

/**
 * Reassembles one node's acceleration bursts from their chunks (docs/protocols/sunspot.md, "Person node"), by burst
 * id. A complete burst is delivered once; its trigger time is the arrival of chunk 0 (chunk 0 leaves the node at the
 * trigger), less the time from the trigger sample to chunk 0's last sample if chunk 0 holds samples taken after it.
 * A burst is given up, with a reason in words, when chunks disagree on its count, rate or trigger position, an index
 * repeats, a new chunk 0 arrives for an incomplete burst of the same id, or it is overdue: N · 32 / R s + 2 s after
 * its first chunk. Thread-safe (one lock; a node's frames arrive on one thread anyway).
 */
final class BurstAssembler {

    /** Extra wait for the last chunk of a burst beyond the time its samples take, for radio delays. */
    static final Duration GRACE = Duration.ofSeconds(2);

    /** What one chunk led to: a complete burst, and the bursts given up, each in words. */
    record Outcome(Optional<AccelerationBurst> burst, List<String> givenUp) {
    }

    private static final class Pending {
        final BurstChunk first;
        final BurstChunk[] chunks;
        final Instant firstArrival;
        final Instant due;
        Instant chunk0Arrival;
        int received;

        Pending(BurstChunk first, Instant at) {
            this.first = first;
            this.chunks = new BurstChunk[first.chunkCount()];
            this.firstArrival = at;
            this.due = at.plus(Duration.ofMillis(1000L * first.chunkCount() * BurstChunk.MAX_SAMPLES
                    / first.sampleRateHz())).plus(GRACE);
        }

        String disagreement(BurstChunk c) {
            if (c.chunkCount() != first.chunkCount()) {
                return "chunk " + c.chunkIndex() + " says " + c.chunkCount() + " chunks, the first said "
                        + first.chunkCount();
            }
            if (c.sampleRateHz() != first.sampleRateHz()) {
                return "chunk " + c.chunkIndex() + " says " + c.sampleRateHz() + " Hz, the first said "
                        + first.sampleRateHz() + " Hz";
            }
            if (c.samplesBeforeTrigger() != first.samplesBeforeTrigger()) {
                return "chunk " + c.chunkIndex() + " puts the trigger after " + c.samplesBeforeTrigger()
                        + " samples, the first after " + first.samplesBeforeTrigger();
            }
            return chunks[c.chunkIndex()] != null ? "chunk " + c.chunkIndex() + " arrived twice" : null;
        }

        String words(String why) {
            return "acceleration burst " + first.burstId() + " given up: " + received + " of its "
                    + first.chunkCount() + " chunks arrived, " + why
                    + "; the movement summaries still tell the posture and stillness after it";
        }
    }

    private final Map<Integer, Pending> pending = new HashMap<>();

    /**
     * @param chunk a decoded chunk (each chunk was checked alone by the protocol library)
     * @param at    its arrival
     * @return the burst it completed, if any, and the bursts given up meanwhile
     */
    synchronized Outcome add(BurstChunk chunk, Instant at) {
        List<String> givenUp = new ArrayList<>(expire(at));
        Pending p = pending.get(chunk.burstId());
        if (p != null && chunk.chunkIndex() == 0 && p.chunks[0] != null) {
            pending.remove(chunk.burstId());
            givenUp.add(p.words("a new burst with the same id began (the node restarted or its count wrapped)"));
            p = null;
        }
        if (p != null) {
            String why = p.disagreement(chunk);
            if (why != null) {
                pending.remove(chunk.burstId());
                givenUp.add(p.words(why));
                return new Outcome(Optional.empty(), givenUp);
            }
        } else {
            p = new Pending(chunk, at);
            pending.put(chunk.burstId(), p);
        }
        p.chunks[chunk.chunkIndex()] = chunk;
        p.received++;
        if (chunk.chunkIndex() == 0) {
            p.chunk0Arrival = at;
        }
        if (p.received < p.chunks.length) {
            return new Outcome(Optional.empty(), givenUp);
        }
        pending.remove(chunk.burstId());
        return new Outcome(Optional.of(burst(p)), givenUp);
    }

    /** @return the bursts overdue at {@code now}, given up, each in words */
    synchronized List<String> expire(Instant now) {
        List<String> givenUp = new ArrayList<>();
        for (Iterator<Pending> it = pending.values().iterator(); it.hasNext();) {
            Pending p = it.next();
            if (now.isAfter(p.due)) {
                it.remove();
                givenUp.add(p.words("the others did not arrive within "
                        + Duration.between(p.firstArrival, p.due).toMillis() / 1000.0 + " s of the first"));
            }
        }
        return givenUp;
    }

    /** @return how many bursts are incomplete */
    synchronized int pendingCount() {
        return pending.size();
    }

    private static AccelerationBurst burst(Pending p) {
        List<Acceleration> samples = new ArrayList<>();
        for (BurstChunk c : p.chunks) {
            c.samples().forEach(s -> samples.add(PersonReport.acceleration(s)));
        }
        int before = p.first.samplesBeforeTrigger();
        int rate = p.first.sampleRateHz();
        int afterInChunk0 = Math.max(0, p.chunks[0].samples().size() - 1 - before);
        Instant trigger = p.chunk0Arrival.minusNanos(afterInChunk0 * 1_000_000_000L / rate);
        return new AccelerationBurst(trigger, rate, before, samples);
    }
}

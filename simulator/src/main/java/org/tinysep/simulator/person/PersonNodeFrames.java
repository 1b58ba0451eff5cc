package org.tinysep.simulator.person;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.sunspot.protocol.AccelerationSample;
import org.tinysep.sunspot.protocol.BurstChunk;
import org.tinysep.sunspot.protocol.MovementSummaryReport;
import org.tinysep.sunspot.protocol.SunSpotAddress;
import org.tinysep.sunspot.protocol.SunSpotCodec;
import org.tinysep.sunspot.protocol.SunSpotFrame;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;

/**
 * The person node's radio: the rule's summaries and bursts as Sun SPOT frames (sensor type 6,
 * docs/protocols/sunspot.md "Person node"), each at the instant the node sends it. A summary goes out when its
 * period ends; a burst's chunk 0 at the trigger, every later chunk as soon as its last sample is taken.
 */
public final class PersonNodeFrames implements PersonNodeRule.Output {

    /** One frame and when the node sends it. */
    public record Timed(Instant at, byte[] frame, SunSpotPayload payload) {
    }

    private final SunSpotAddress address;
    private final List<Timed> frames = new ArrayList<>();
    private int burstId;

    public PersonNodeFrames(SunSpotAddress address) {
        this.address = address;
    }

    @Override
    public void summary(Instant at, MovementSummary s) {
        add(at, new MovementSummaryReport((int) s.span().toMillis(), sample(s.mean()), s.magnitudeSdMg(),
                s.peakMg()));
    }

    @Override
    public void burst(Instant at, AccelerationBurst b) {
        List<AccelerationSample> samples = b.samples().stream().map(PersonNodeFrames::sample).toList();
        List<BurstChunk> chunks = BurstChunk.split(burstId, b.sampleRateHz(), b.samplesBeforeTrigger(), samples);
        burstId = (burstId + 1) & 0xFF;
        long periodNanos = 1_000_000_000L / b.sampleRateHz();
        for (BurstChunk c : chunks) {
            int last = c.chunkIndex() * BurstChunk.MAX_SAMPLES + c.samples().size() - 1;
            Instant taken = b.trigger().plusNanos((last - b.samplesBeforeTrigger()) * periodNanos);
            add(taken.isBefore(b.trigger()) ? b.trigger() : taken, c);
        }
    }

    private void add(Instant at, SunSpotPayload payload) {
        frames.add(new Timed(at, SunSpotCodec.encode(SunSpotFrame.of(address, SunSpotPayloads.encode(payload))),
                payload));
    }

    /** @return every frame so far, in the order the node sends them */
    public List<Timed> frames() {
        List<Timed> sorted = new ArrayList<>(frames);
        sorted.sort(Comparator.comparing(Timed::at)); // stable: a summary and a chunk of the same instant keep order
        return sorted;
    }

    /** @return every frame so far, in the order the node sends them, and forgets them (a live node's radio) */
    public List<Timed> drain() {
        List<Timed> sorted = frames();
        frames.clear();
        return sorted;
    }

    private static AccelerationSample sample(Acceleration a) {
        return new AccelerationSample(a.xMg(), a.yMg(), a.zMg());
    }

    /** @return the frames the node sends for {@code samples} taken every 20 ms from {@code start} */
    public static List<Timed> of(SunSpotAddress address, Instant start, List<Acceleration> samples) {
        PersonNodeFrames out = new PersonNodeFrames(address);
        PersonNodeRule rule = new PersonNodeRule(out);
        long period = 1000L / PersonNodeRule.RATE_HZ;
        for (int i = 0; i < samples.size(); i++) {
            rule.sample(start.plusMillis(period * i), samples.get(i));
        }
        return out.frames();
    }
}

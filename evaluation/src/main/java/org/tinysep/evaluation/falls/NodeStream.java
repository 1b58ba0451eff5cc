package org.tinysep.evaluation.falls;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.simulator.person.NodeResampler;
import org.tinysep.simulator.person.PersonNodeRule;
import org.tinysep.simulator.person.RadioBudget;
import org.tinysep.simulator.person.SisfallRecording;

/**
 * One SisFall recording as the person node sends it: resampled and clipped ({@link NodeResampler}), followed by
 * {@value #REST_SECONDS} s of rest (the mean of its last second, repeated: the person lies or stands still after the
 * recording ends, so a fall at its end can still be confirmed), through the node's rule ({@link PersonNodeRule}).
 *
 * @param recording the recording (its name, code, subject)
 * @param events    what the node sent, in order, each at the instant it was complete
 * @param impact    the instant of the recording's largest magnitude at 200 Hz (a fall's impact)
 * @param recorded  the recording's length without the padding
 * @param budget    the radio budget of the recorded part (frames sent while the recording lasted)
 * @param samples   the node's 50 Hz samples, padding included (what the platform runs play over UDP)
 */
record NodeStream(SisfallRecording recording, List<Event> events, Instant impact, Duration recorded,
        RadioBudget budget, List<Acceleration> samples) {

    static final int REST_SECONDS = 20;
    static final Instant T0 = Instant.parse("2026-01-05T09:00:00Z");

    /** A summary or a burst, arriving at {@code at}. */
    record Event(Instant at, MovementSummary summary, AccelerationBurst burst) {
    }

    static NodeStream of(SisfallRecording r) {
        List<Acceleration> samples = new ArrayList<>(NodeResampler.toNode(r));
        int recordedSamples = samples.size();
        int rate = NodeResampler.NODE_RATE_HZ;
        Acceleration rest = Acceleration.mean(samples.subList(Math.max(0, recordedSamples - rate), recordedSamples));
        for (int i = 0; i < REST_SECONDS * rate; i++) {
            samples.add(rest);
        }
        List<Event> events = new ArrayList<>();
        RadioBudget budget = new RadioBudget();
        Instant end = T0.plusMillis(1000L * recordedSamples / rate);
        PersonNodeRule rule = new PersonNodeRule(new PersonNodeRule.Output() {
            @Override
            public void summary(Instant at, MovementSummary s) {
                events.add(new Event(at, s, null));
                if (!at.isAfter(end)) {
                    budget.summary();
                }
            }

            @Override
            public void burst(Instant at, AccelerationBurst b) {
                events.add(new Event(at, null, b));
                if (!b.trigger().isAfter(end)) {
                    budget.burst(b.samples().size());
                }
            }
        });
        for (int i = 0; i < samples.size(); i++) {
            rule.sample(T0.plusMillis(1000L * i / rate), samples.get(i));
        }
        Duration recorded = Duration.ofMillis(1000L * recordedSamples / rate);
        budget.recorded(recorded);
        Instant impact = T0.plusMillis(1000L * r.peakIndex() / SisfallRecording.RATE_HZ);
        return new NodeStream(r, List.copyOf(events), impact, recorded, budget, List.copyOf(samples));
    }
}

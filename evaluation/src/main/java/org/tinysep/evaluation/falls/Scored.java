package org.tinysep.evaluation.falls;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.falldetection.internal.Fall;
import org.tinysep.falldetection.internal.FallDetector;
import org.tinysep.falldetection.internal.FallSettings;
import org.tinysep.simulator.person.NodeResampler;

/**
 * One recording judged: the FALL alerts a detector raised on it. A fall recording is detected when an alert came
 * between the impact and 30 s after it; an ADL recording is correct when it has no alert at all.
 *
 * @param stream   the recording as the node sent it
 * @param alerts   when each alert was raised
 * @param refused  bursts the detector refused (impossible values), with its words
 * @param upright  the wearer's upright the detector had learned when the recording began (null: none yet)
 */
record Scored(NodeStream stream, List<Instant> alerts, List<String> refused, Acceleration upright) {

    static final Duration WINDOW = Duration.ofSeconds(30);
    /** Seconds of virtual time between two recordings of a subject, as through the platform (FallPlatforms). */
    static final long GAP_S = 40;

    /** One recording into a fresh detector that knows {@code upright} (null: not yet learned). */
    static Scored run(NodeStream s, FallSettings settings, Acceleration upright) {
        FallDetector d = upright == null ? new FallDetector(settings) : new FallDetector(settings, upright);
        return play(d, s, Duration.ZERO);
    }

    /**
     * A subject's recordings one after another ({@value #GAP_S} s apart, as the platform plays them) into one
     * detector, as the worn node would feed it: what it learned of the wearer (the upright) carries over.
     */
    static List<Scored> runSubject(List<NodeStream> streams, FallSettings settings) {
        FallDetector d = new FallDetector(settings);
        List<Scored> out = new ArrayList<>();
        Duration offset = Duration.ZERO;
        for (NodeStream s : streams) {
            out.add(play(d, s, offset));
            long played = (s.samples().size() * 1000L / NodeResampler.NODE_RATE_HZ + 999) / 1000;
            offset = offset.plusSeconds(played + GAP_S);
        }
        return out;
    }

    private static Scored play(FallDetector d, NodeStream s, Duration offset) {
        Acceleration upright = d.upright().orElse(null);
        List<Instant> alerts = new ArrayList<>();
        List<String> refused = new ArrayList<>();
        for (NodeStream.Event e : s.events()) {
            Optional<Fall> f;
            if (e.summary() != null) {
                MovementSummary m = e.summary();
                f = d.summary(new MovementSummary(m.end().plus(offset), m.span(), m.mean(), m.magnitudeSdMg(),
                        m.peakMg()));
            } else {
                AccelerationBurst b = e.burst();
                try {
                    f = d.burst(new AccelerationBurst(b.trigger().plus(offset), b.sampleRateHz(),
                            b.samplesBeforeTrigger(), b.samples()));
                } catch (IllegalArgumentException x) {
                    refused.add(x.getMessage());
                    continue;
                }
            }
            f.ifPresent(fall -> alerts.add(e.at()));
        }
        return new Scored(s, List.copyOf(alerts), List.copyOf(refused), upright);
    }

    boolean fall() {
        return stream.recording().isFall();
    }

    /** @return the delay from the impact to the first alert within the window, if any */
    Optional<Duration> delay() {
        Instant impact = stream.impact();
        return alerts.stream().filter(a -> !a.isBefore(impact) && !a.isAfter(impact.plus(WINDOW))).findFirst()
                .map(a -> Duration.between(impact, a));
    }

    /** @return whether the detector was right: a fall alerted in time, an ADL left alone */
    boolean correct() {
        return fall() ? delay().isPresent() : alerts.isEmpty();
    }
}

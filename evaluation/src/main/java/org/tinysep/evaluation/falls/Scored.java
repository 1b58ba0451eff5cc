package org.tinysep.evaluation.falls;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.tinysep.falldetection.internal.Fall;
import org.tinysep.falldetection.internal.FallDetector;
import org.tinysep.falldetection.internal.FallSettings;

/**
 * One recording judged: the FALL alerts a detector raised on it. A fall recording is detected when an alert came
 * between the impact and 30 s after it; an ADL recording is correct when it has no alert at all.
 *
 * @param stream   the recording as the node sent it
 * @param alerts   when each alert was raised
 * @param refused  bursts the detector refused (impossible values), with its words
 */
record Scored(NodeStream stream, List<Instant> alerts, List<String> refused) {

    static final Duration WINDOW = Duration.ofSeconds(30);

    static Scored run(NodeStream s, FallSettings settings) {
        FallDetector d = new FallDetector(settings);
        List<Instant> alerts = new ArrayList<>();
        List<String> refused = new ArrayList<>();
        for (NodeStream.Event e : s.events()) {
            Optional<Fall> f;
            if (e.summary() != null) {
                f = d.summary(e.summary());
            } else {
                try {
                    f = d.burst(e.burst());
                } catch (IllegalArgumentException x) {
                    refused.add(x.getMessage());
                    continue;
                }
            }
            f.ifPresent(fall -> alerts.add(e.at()));
        }
        return new Scored(s, List.copyOf(alerts), List.copyOf(refused));
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

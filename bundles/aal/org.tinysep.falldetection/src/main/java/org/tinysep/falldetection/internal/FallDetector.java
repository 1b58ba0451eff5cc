package org.tinysep.falldetection.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.api.sensor.person.AccelerationBurst;
import org.tinysep.api.sensor.person.MovementSummary;

/**
 * The algorithm for one person node (README "Algorithm"): a burst whose peak reaches the impact level opens a
 * candidate; it becomes a fall when, within {@code within} after the impact, the node's summaries show stillness
 * (SD at most {@code stillSdMg}) for {@code stillFor} in a posture at least {@code postureChangeDeg} away from the one
 * before the impact. An impact while the body was already lying (at least {@code alreadyLyingDeg} from the wearer's
 * upright, learned by {@link Upright}) opens none. Not thread-safe: one caller at a time (the listener synchronises).
 */
public final class FallDetector {

    /** Largest magnitude a sample may claim (three axes at ±16 g, more than any accelerometer on a node), mg. */
    static final double IMPOSSIBLE_MG = 16_000 * Math.sqrt(3) + 1;
    private static final Duration KEEP = Duration.ofSeconds(90);
    /**
     * How much earlier than the impact a still summary may seem to begin: the platform stamps a report with the
     * whole second it arrived in, up to 1 s early. A summary that really held the impact is not still anyway.
     */
    static final Duration STAMP_TOLERANCE = Duration.ofSeconds(1);
    /** A summary that ended longer than this before the trigger does not tell the posture before it. */
    static final Duration POSTURE_BEFORE_AGE = Duration.ofSeconds(4);

    private record Candidate(Instant impact, int peakMg, Acceleration before) {
    }

    private final FallSettings settings;
    private final ArrayDeque<MovementSummary> summaries = new ArrayDeque<>();
    private final List<Candidate> candidates = new ArrayList<>();
    private final Upright upright = new Upright();

    public FallDetector(FallSettings settings) {
        this.settings = settings;
    }

    /** @return the wearer's upright in the node's axes, once the detector has seen them walk ({@link Upright}) */
    public Optional<Acceleration> upright() {
        return upright.get();
    }

    /**
     * A detector for a wearer whose upright is already known (learned by another detector of the same node, e.g.
     * before a restart); it goes on learning from the summaries it is given.
     */
    public FallDetector(FallSettings settings, Acceleration knownUpright) {
        this(settings);
        upright.seed(knownUpright);
    }

    /**
     * A burst arrived.
     *
     * @return a fall, when the summaries already received complete one
     * @throws IllegalArgumentException for a burst no accelerometer could have sent (refused, not a fall)
     */
    public Optional<Fall> burst(AccelerationBurst b) {
        List<Acceleration> s = b.samples();
        if (b.sampleRateHz() < 5 || b.sampleRateHz() > 2000) {
            throw new IllegalArgumentException("a burst at " + b.sampleRateHz() + " Hz is not a rate a person "
                    + "node samples at (5..2000 Hz); refused");
        }
        int peakAt = -1;
        double peak = 0;
        for (int i = 0; i < s.size(); i++) {
            double m = s.get(i).magnitudeMg();
            if (m > IMPOSSIBLE_MG) {
                throw new IllegalArgumentException("a burst sample of " + Math.round(m) + " mg is more than any "
                        + "person node's accelerometer measures (at most 16 g per axis); refused");
            }
            if (m > peak) {
                peak = m;
                peakAt = i;
            }
        }
        if (peakAt < 0 || peak < settings.impactMg()) {
            return Optional.empty();
        }
        Instant impact = b.trigger().plusNanos(
                (peakAt - b.samplesBeforeTrigger()) * 1_000_000_000L / b.sampleRateHz());
        Acceleration before = postureBefore(b);
        if (alreadyLying(before)) {
            return Optional.empty(); // turning over or getting up from lying: not a fall from standing or sitting
        }
        candidates.add(new Candidate(impact, (int) Math.round(peak), before));
        return check();
    }

    /** A movement summary arrived: @return a fall, when it completes one */
    public Optional<Fall> summary(MovementSummary m) {
        summaries.addLast(m);
        upright.summary(m);
        while (!summaries.isEmpty() && summaries.peekFirst().end().isBefore(m.end().minus(KEEP))) {
            summaries.removeFirst();
        }
        return check();
    }

    /**
     * The mean of the last summary that ended before the trigger (at most 4 s before it), else of the burst's samples
     * before the trigger (the node was just switched on, or summaries were lost). Strictly before: the platform
     * stamps reports with its whole second, so a summary stamped in the trigger's second may have ended after it
     * and hold the fall itself.
     */
    private Acceleration postureBefore(AccelerationBurst b) {
        MovementSummary last = null;
        for (MovementSummary m : summaries) {
            if (m.end().isBefore(b.trigger()) && !m.end().isBefore(b.trigger().minus(POSTURE_BEFORE_AGE))) {
                last = m;
            }
        }
        if (last != null) {
            return last.mean();
        }
        List<Acceleration> pre = b.samples().subList(0, Math.max(1, b.samplesBeforeTrigger()));
        return Acceleration.mean(pre);
    }

    private Optional<Fall> check() {
        Instant latest = summaries.isEmpty() ? Instant.MIN : summaries.peekLast().end();
        for (Iterator<Candidate> it = candidates.iterator(); it.hasNext();) {
            Candidate c = it.next();
            Optional<Fall> fall = fallAfter(c);
            if (fall.isPresent()) {
                Instant at = fall.get().detectedAt();
                candidates.removeIf(other -> !other.impact().isAfter(at));
                return fall;
            }
            if (latest.isAfter(c.impact().plus(settings.within()).plus(settings.stillFor()))) {
                it.remove(); // no stillness began within the window: not a fall
            }
        }
        return Optional.empty();
    }

    /** The first run of still summaries after the impact that is long enough and in a new posture. */
    private Optional<Fall> fallAfter(Candidate c) {
        List<MovementSummary> run = new ArrayList<>();
        Instant limit = c.impact().plus(settings.within());
        for (MovementSummary m : summaries) {
            Instant start = m.end().minus(m.span());
            if (start.isBefore(c.impact().minus(STAMP_TOLERANCE))) {
                continue;
            }
            if (m.magnitudeSdMg() > settings.stillSdMg()) {
                run.clear();
                continue;
            }
            if (run.isEmpty() && start.isAfter(limit)) {
                break;
            }
            run.add(m);
            Duration still = Duration.between(run.get(0).end().minus(run.get(0).span()), m.end());
            if (still.compareTo(settings.stillFor()) >= 0) {
                Acceleration after = Acceleration.mean(run.stream().map(MovementSummary::mean).toList());
                double angle = angle(c.before(), after);
                if (angle >= settings.postureChangeDeg()) {
                    return Optional.of(new Fall(c.impact(), c.peakMg(), c.before(), after, angle, still, m.end()));
                }
                run.remove(0); // still but upright as before: slide on, the posture may yet change
            }
        }
        return Optional.empty();
    }

    /**
     * @return whether the posture before an impact is at least {@code alreadyLyingDeg} from the wearer's learned
     *         upright (never while the upright is unknown, nor with the rule off at 180°)
     */
    private boolean alreadyLying(Acceleration before) {
        return settings.alreadyLyingDeg() < 180 && upright.get()
                .map(u -> angle(u, before) >= settings.alreadyLyingDeg()).orElse(false);
    }

    /** @return the angle between two vectors, degrees (0 when either is zero) */
    static double angle(Acceleration a, Acceleration b) {
        double na = a.magnitudeMg();
        double nb = b.magnitudeMg();
        if (na == 0 || nb == 0) {
            return 0;
        }
        double dot = (double) a.xMg() * b.xMg() + (double) a.yMg() * b.yMg() + (double) a.zMg() * b.zMg();
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, dot / (na * nb)))));
    }
}

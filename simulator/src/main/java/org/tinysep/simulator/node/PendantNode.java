package org.tinysep.simulator.node;

import java.io.IOException;
import java.io.InputStream;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Random;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.simulator.flat.NodeSpec;
import org.tinysep.simulator.person.NodeResampler;
import org.tinysep.simulator.person.PersonNodeFrames;
import org.tinysep.simulator.person.PersonNodeRule;
import org.tinysep.simulator.person.SisfallRecording;
import org.tinysep.sunspot.protocol.SunSpotAddress;

/**
 * A Sun SPOT person node worn by a person of the scenario (node type {@code person}, option {@code agent=<name>}):
 * every second 50 accelerometer samples go through the node's own rule ({@link PersonNodeRule}: a
 * summary every 2 s, a burst around a peak of 2 g) and its frames go out over the Sun SPOT radio. What it feels
 * follows the wearer: moving about (upright, swaying as in walking, no peak near 2 g), lying still asleep, nothing
 * while away (out of the radio's range). When the wearer collapses it plays a fall recording — {@value #FALL}, a
 * synthetic recording in SisFall's format committed with the simulator (resources {@code recordings/}, see its
 * PROVENANCE.md) — then lies still. Every frame goes out at the instant the node sends it, milliseconds kept: at
 * second {@code t} the node takes the samples of {@code (t, t + 1]}, so its summaries end on whole seconds, and a
 * burst's chunks, which fall inside a second, are due at their own instants ({@link #dueWithin}: the lock-step
 * driver TICKs the platform to each, so the radio stamps a burst with its trigger, not its whole second).
 */
public final class PendantNode extends SimNode {

    /** The fall played at a collapse (the impact comes 4.4 s after the collapse's start). */
    public static final String FALL = "F01_SX01_R01.txt.gz";
    /** After the recording the node lies still this long before it is fed second by second again. */
    private static final int LYING_AFTER_S = 30;
    private static final Acceleration LYING = new Acceleration(30, -80, 995);
    private static final long PERIOD_MS = 1000L / PersonNodeRule.RATE_HZ;

    private final SunSpotAddress address;
    private final SunSpotPort port;
    private final Environment env;
    private final List<Acceleration> fall;
    private final Random noise;
    private final Deque<PersonNodeFrames.Timed> queued = new ArrayDeque<>();
    private PersonNodeFrames radio;
    private PersonNodeRule rule;
    private long collapsePlayed = Long.MIN_VALUE;
    /** The last frame of the fall being sent; routine samples resume after it. */
    private Instant fallUntil = Instant.MIN;

    PendantNode(NodeSpec spec, SunSpotPort port, Environment env, List<Acceleration> fall) {
        super(spec);
        this.address = SunSpotAddress.parse(spec.address());
        this.port = port;
        this.env = env;
        this.fall = List.copyOf(fall);
        this.noise = new Random(spec.address().hashCode());
        restart();
    }

    /** @return the fall recording at the node's rate and range */
    public static List<Acceleration> fallRecording() throws IOException {
        try (InputStream in = PendantNode.class.getResourceAsStream("/recordings/" + FALL)) {
            if (in == null) {
                throw new IOException("the simulator's fall recording recordings/" + FALL + " is missing");
            }
            return NodeResampler.toNode(SisfallRecording.read(FALL, in));
        }
    }

    private void restart() {
        radio = new PersonNodeFrames(address);
        rule = new PersonNodeRule(radio);
    }

    @Override
    protected int report(long t, long elapsed) {
        Wearer w = env.wearer(spec.carriedBy());
        Instant second = Instant.ofEpochSecond(t);
        if (w.state() == Wearer.State.AWAY) {
            queued.clear(); // out of range: nothing of it reaches the platform
            return 0;
        }
        int sent = sendDue(second); // what the last second's samples made, due now
        if (w.state() == Wearer.State.COLLAPSED && w.since() != collapsePlayed) {
            collapsePlayed = w.since();
            List<Acceleration> samples = new ArrayList<>(fall);
            for (int i = 0; i < LYING_AFTER_S * PersonNodeRule.RATE_HZ; i++) {
                samples.add(lying());
            }
            queued.clear();
            // the first sample 20 ms after this second: summaries end on whole seconds, a burst inside one
            List<PersonNodeFrames.Timed> frames = PersonNodeFrames.of(address, second.plusMillis(PERIOD_MS), samples);
            queued.addAll(frames);
            fallUntil = frames.isEmpty() ? second : frames.get(frames.size() - 1).at();
            restart();
        }
        if (second.isBefore(fallUntil)) {
            return sent; // the fall is still being sent
        }
        // the samples of the coming second, (t, t + 1]: its frames leave at their own instants
        for (int i = 1; i <= PersonNodeRule.RATE_HZ; i++) {
            double at = i / (double) PersonNodeRule.RATE_HZ + t % 600;
            rule.sample(second.plusMillis(PERIOD_MS * i), w.state() == Wearer.State.ACTIVE ? moving(at) : lying());
        }
        queued.addAll(radio.drain());
        return sent;
    }

    /** @return the instants inside second {@code t} at which a frame leaves (a burst's chunks; summaries end on whole seconds) */
    @Override
    public List<Instant> dueWithin(long t) {
        Instant from = Instant.ofEpochSecond(t);
        Instant to = from.plusSeconds(1);
        List<Instant> due = new ArrayList<>();
        for (PersonNodeFrames.Timed f : queued) {
            if (f.at().isAfter(from) && f.at().isBefore(to) && (due.isEmpty() || f.at().isAfter(due.get(due.size() - 1)))) {
                due.add(f.at());
            }
        }
        return due;
    }

    /**
     * Sends every queued frame due by {@code at}, in order.
     *
     * @return how many frames of a fall were sent (paced, so the radio keeps up); a routine summary counts 0
     */
    @Override
    public int sendDue(Instant at) {
        int sent = 0;
        while (!queued.isEmpty() && !queued.peek().at().isAfter(at)) {
            PersonNodeFrames.Timed f = queued.poll();
            port.send(address, f.payload());
            if (!f.at().isAfter(fallUntil)) {
                sent++;
            }
        }
        return sent;
    }

    /** Upright (the node's y axis down), swaying at a walking pace: about 1.3 g at most. */
    private Acceleration moving(double s) {
        double step = 0.25 * Math.sin(2 * Math.PI * 1.8 * s);
        return new Acceleration(jitter(0), (int) Math.round(-1000 * (1 + step)) + jitter(0), jitter(50));
    }

    private Acceleration lying() {
        return new Acceleration(LYING.xMg() + jitter(0), LYING.yMg() + jitter(0), LYING.zMg() + jitter(0));
    }

    private int jitter(int around) {
        return around + (int) Math.round(noise.nextGaussian() * 8);
    }
}

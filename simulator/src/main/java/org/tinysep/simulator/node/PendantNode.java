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
 * every second its 50 accelerometer samples go through the node's own rule ({@link PersonNodeRule}: a
 * summary every 2 s, a burst around a peak of 2 g) and its frames go out over the Sun SPOT radio. What it feels
 * follows the wearer: moving about (upright, swaying as in walking, no peak near 2 g), lying still asleep, nothing
 * while away (out of the radio's range). When the wearer collapses it plays a fall recording — {@value #FALL}, a
 * synthetic recording in SisFall's format committed with the simulator (resources {@code recordings/}, see its
 * PROVENANCE.md) — then lies still; those frames go out at the instants the node sends them.
 */
public final class PendantNode extends SimNode {

    /** The fall played at a collapse (the impact comes 4.4 s after the collapse's start). */
    public static final String FALL = "F01_SX01_R01.txt.gz";
    /** After the recording the node lies still this long before it is fed second by second again. */
    private static final int LYING_AFTER_S = 30;
    private static final Acceleration LYING = new Acceleration(30, -80, 995);

    private final SunSpotAddress address;
    private final SunSpotPort port;
    private final Environment env;
    private final List<Acceleration> fall;
    private final Random noise;
    private final Deque<PersonNodeFrames.Timed> queued = new ArrayDeque<>();
    private PersonNodeFrames radio;
    private PersonNodeRule rule;
    private long collapsePlayed = Long.MIN_VALUE;

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
        if (w.state() == Wearer.State.AWAY) {
            queued.clear(); // out of range: nothing of it reaches the platform
            return 0;
        }
        if (w.state() == Wearer.State.COLLAPSED && w.since() != collapsePlayed) {
            collapsePlayed = w.since();
            List<Acceleration> samples = new ArrayList<>(fall);
            for (int i = 0; i < LYING_AFTER_S * PersonNodeRule.RATE_HZ; i++) {
                samples.add(lying());
            }
            queued.clear();
            queued.addAll(PersonNodeFrames.of(address, Instant.ofEpochSecond(t), samples));
            restart();
        }
        if (!queued.isEmpty()) { // the fall: frames at their own instants; paced, so the radio keeps up
            int sent = 0;
            while (!queued.isEmpty() && queued.peek().at().getEpochSecond() <= t) {
                port.send(address, queued.poll().payload());
                sent++;
            }
            return sent;
        }
        Instant second = Instant.ofEpochSecond(t);
        for (int i = 0; i < PersonNodeRule.RATE_HZ; i++) {
            double at = i / (double) PersonNodeRule.RATE_HZ + t % 600;
            rule.sample(second.plusMillis(1000L * i / PersonNodeRule.RATE_HZ),
                    w.state() == Wearer.State.ACTIVE ? moving(at) : lying());
        }
        for (PersonNodeFrames.Timed f : radio.drain()) {
            port.send(address, f.payload());
        }
        return 0; // a summary every 2 s is routine: not paced
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

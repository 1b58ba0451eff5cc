package org.tinysep.simulator.person;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.simulator.time.LockStepDriver;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.simulator.time.VirtualClock;

/**
 * Plays a person node's frames ({@link PersonNodeFrames}) to the Sun SPOT UDP bus radio in lock-step time: for each
 * instant that has frames, the platform is TICKed to that very instant (milliseconds kept), then that instant's
 * frames go out in order, so the radio stamps each with the instant the node sent it (a burst's trigger 4.42 s in,
 * not 4 s: before, whole seconds were played and instants inside a second were rounded down to it).
 */
public final class PersonNodePlayer implements AutoCloseable {

    private final DatagramChannel channel;
    private final InetSocketAddress radio;

    /** @param radio the Sun SPOT bus radio, e.g. {@code Target.sunSpot()} (127.0.0.1 in tests) */
    public PersonNodePlayer(InetSocketAddress radio) throws IOException {
        this.radio = radio;
        this.channel = DatagramChannel.open().bind(new InetSocketAddress(radio.getAddress().isLoopbackAddress()
                ? java.net.InetAddress.getLoopbackAddress() : null, 0));
    }

    /**
     * Plays {@code frames} (sorted by time) from their first instant to {@code until}, TICKing only the instants
     * that have frames (as they are, with their milliseconds) and then {@code until} itself.
     *
     * @return how many frames were sent
     */
    public int play(SyncClient sync, List<PersonNodeFrames.Timed> frames, Instant until, long paceNanos)
            throws Exception {
        if (frames.isEmpty()) {
            return 0;
        }
        List<Instant> instants = new ArrayList<>();
        for (PersonNodeFrames.Timed f : frames) {
            if (instants.isEmpty() || f.at().isAfter(instants.get(instants.size() - 1))) {
                instants.add(f.at());
            }
        }
        instants.add(until);
        int[] next = {0};
        long[] sent = {0};
        new LockStepDriver(sync, new VirtualClock(frames.get(0).at()), paceNanos).runInstants(instants, t -> {
            int n = 0;
            while (next[0] < frames.size() && !frames.get(next[0]).at().isAfter(t)) {
                channel.send(ByteBuffer.wrap(frames.get(next[0]++).frame()), radio);
                n++;
            }
            sent[0] += n;
            return n;
        });
        return (int) sent[0];
    }

    @Override
    public void close() throws IOException {
        channel.close();
    }
}

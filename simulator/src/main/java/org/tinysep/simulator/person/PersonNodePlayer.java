package org.tinysep.simulator.person;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.time.Instant;
import java.util.List;
import org.tinysep.simulator.time.LockStepDriver;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.simulator.time.VirtualClock;

/**
 * Plays a person node's frames ({@link PersonNodeFrames}) to the Sun SPOT UDP bus radio in lock-step time: for each
 * second that has frames, the platform is TICKed to it, then that second's frames go out in order (the radio stamps
 * them with that second, so instants inside a second are rounded down to it).
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
     * Plays {@code frames} (sorted by time) from their first second to {@code until}, TICKing only the seconds that
     * have frames and then {@code until} itself.
     *
     * @return how many frames were sent
     */
    public int play(SyncClient sync, List<PersonNodeFrames.Timed> frames, Instant until, long paceNanos)
            throws Exception {
        if (frames.isEmpty()) {
            return 0;
        }
        Instant from = second(frames.get(0).at());
        int[] next = {0};
        long[] sent = {0};
        new LockStepDriver(sync, new VirtualClock(from), paceNanos).run(from, until.plusSeconds(1), t -> {
            int n = 0;
            while (next[0] < frames.size() && !second(frames.get(next[0]).at()).isAfter(t)) {
                channel.send(ByteBuffer.wrap(frames.get(next[0]++).frame()), radio);
                n++;
            }
            sent[0] += n;
            return n;
        }, t -> Math.max(t + 1, next[0] < frames.size() ? second(frames.get(next[0]).at()).getEpochSecond()
                : until.getEpochSecond()));
        return (int) sent[0];
    }

    private static Instant second(Instant i) {
        return Instant.ofEpochSecond(i.getEpochSecond());
    }

    @Override
    public void close() throws IOException {
        channel.close();
    }
}

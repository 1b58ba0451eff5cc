package org.tinysep.link.frame.testing;

import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import org.tinysep.link.frame.FrameStream;

/**
 * The test sink of both families' stream decoders: records what a decoder reports, as readable strings in order. A
 * family's {@code RecordingSink} is this class with the family's sink interface. A run without a reason or with a
 * length outside 1..{@value FrameStream#BUFFER_SIZE} fails the test at once (and is kept in {@link #badRun}).
 *
 * @param <F> the frame
 * @param <R> the reject reason
 */
public class Recording<F, R> implements FrameStream.Sink<F, R> {

    /** Frames as their {@code toString()}, runs as {@code "REASON n"}, in order. */
    public final List<String> events = new ArrayList<>();
    /** The frames received, in order. */
    public final List<F> frameList = new ArrayList<>();
    /** Bytes reported as dropped. */
    public long skipped;
    /** Frames received. */
    public int frames;
    /** The first run reported without a reason or with a length out of range, or null. */
    public String badRun;

    @Override
    public void frame(F f) {
        frames++;
        frameList.add(f);
        events.add(f.toString());
    }

    @Override
    public void rejected(R r, int skippedBytes) {
        if (r == null || skippedBytes < 1 || skippedBytes > FrameStream.BUFFER_SIZE) {
            badRun = r + " " + skippedBytes;
            fail("run " + badRun);
        }
        skipped += skippedBytes;
        events.add(r + " " + skippedBytes);
    }
}

package org.tinysep.sunspot.protocol;

import java.util.ArrayList;
import java.util.List;

/** Test sink: records what a stream decoder reports, as readable strings in order. */
final class RecordingSink implements SunSpotStreamDecoder.Sink {

    final List<String> events = new ArrayList<>();
    final List<SunSpotFrame> frameList = new ArrayList<>();
    long skipped;
    int frames;
    /** Set when a run was reported without a reason or with a length outside 1..BUFFER_SIZE. */
    String badRun;

    @Override
    public void frame(SunSpotFrame f) {
        frames++;
        frameList.add(f);
        events.add(f.toString());
    }

    @Override
    public void rejected(RejectReason r, int skippedBytes) {
        if (r == null || skippedBytes < 1 || skippedBytes > SunSpotStreamDecoder.BUFFER_SIZE) {
            badRun = r + " " + skippedBytes;
        }
        skipped += skippedBytes;
        events.add(r + " " + skippedBytes);
    }
}

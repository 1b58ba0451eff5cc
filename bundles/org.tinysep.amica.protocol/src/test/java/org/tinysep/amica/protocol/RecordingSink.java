package org.tinysep.amica.protocol;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

/** Test sink: records what a stream decoder reports, as readable strings in order. */
final class RecordingSink implements AmicaStreamDecoder.Sink {

    final List<String> events = new ArrayList<>();
    long skipped;
    int frames;

    @Override
    public void frame(AmicaFrame f) {
        frames++;
        events.add(f.toString());
    }

    @Override
    public void rejected(RejectReason r, int skippedBytes) {
        assertTrue(skippedBytes > 0 && skippedBytes <= AmicaStreamDecoder.BUFFER_SIZE, "run " + skippedBytes);
        skipped += skippedBytes;
        events.add(r + " " + skippedBytes);
    }
}

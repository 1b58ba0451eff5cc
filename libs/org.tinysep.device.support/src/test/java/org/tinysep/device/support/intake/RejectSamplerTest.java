package org.tinysep.device.support.intake;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.device.support.logs.RecordingLogs;

class RejectSamplerTest {

    @Test
    void aFloodKeepsABoundedHistoryAndSaysWhatItDropped() {
        RecordingLogs logs = new RecordingLogs(Instant::now);
        AtomicLong nanos = new AtomicLong();
        RejectSampler s = new RejectSampler(logs.reporter(), "driver", nanos::get);
        for (int i = 0; i < 1_000_000; i++) {
            s.rejected(i % 2 == 0 ? "127.0.0.2:4000" : "127.0.0.3:4001", new byte[] {1, 2}, "BAD_HEADER");
        }
        assertEquals(RejectSampler.BURST, logs.packets().size(), "only the burst is kept");
        nanos.addAndGet(60_000_000_000L);
        s.flush();
        assertEquals(RejectSampler.BURST + 1, logs.packets().size());
        PacketEntry summary = logs.packets().get(logs.packets().size() - 1);
        assertTrue(summary.note().startsWith("999500 rejected frames not kept in the packet log"), summary.note());
        assertTrue(summary.note().contains("499750 from 127.0.0.2") && summary.note().contains("499750 from 127.0.0.3"),
                summary.note());
        s.flush();
        assertEquals(RejectSampler.BURST + 1, logs.packets().size(), "nothing new to summarise");
        // a minute later the budget has 100 more
        for (int i = 0; i < 1000; i++) {
            s.rejected("127.0.0.2:4000", new byte[] {1}, "BAD_HEADER");
        }
        assertEquals(RejectSampler.BURST + 1 + RejectSampler.PER_MINUTE, logs.packets().size());
    }

    @Test
    void aFewRejectsAreAllKept() {
        RecordingLogs logs = new RecordingLogs(Instant::now);
        RejectSampler s = new RejectSampler(logs.reporter(), "driver", () -> 0L);
        for (int i = 0; i < 307; i++) {
            s.rejected("127.0.0.1:5000", new byte[] {(byte) i}, "TRUNCATED");
        }
        s.flushNow();
        assertEquals(307, logs.packets().size());
    }
}

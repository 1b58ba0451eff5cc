package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The newest entries kept per origin (issue 25, item 6); the flood through the shell: {@code FloodHistoryTest}. */
class OriginShareTest {

    @Test
    void sharesAreBoundedPerOriginAndRejectedSendersCannotPushANodeOut() {
        OriginShare<String> share = new OriginShare<>(s -> s.substring(s.indexOf('|') + 1), 3, 2);
        Instant now = Instant.EPOCH;
        for (int i = 0; i < 10; i++) {
            share.add(i + "|node 3.1 via 127.0.0.1:" + i, now);
        }
        for (int i = 0; i < 100; i++) {
            share.add("x|127.0.0." + i + ":5000", now); // rejected frames from many addresses
        }
        List<String> kept = share.all(String::compareTo);
        assertEquals(5, kept.size(), kept.toString()); // 3 of node 3.1, 1 each of the 2 newest other senders
        assertEquals(List.of("7|node 3.1 via 127.0.0.1:7", "8|node 3.1 via 127.0.0.1:8",
                "9|node 3.1 via 127.0.0.1:9"), kept.subList(0, 3));
        assertEquals("127.0.0.4", OriginShare.key("127.0.0.4:5000"));
        assertEquals("node 3.1", OriginShare.key("node 3.1 via 127.0.0.1:1"));
    }
}

package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The live feed polls its log only while a stream is open, and gives each entry to a stream once (issue 14). */
class LiveFeedTest {

    private final List<Long> log = new ArrayList<>();

    private synchronized List<Long> recent(int n) {
        return List.copyOf(log.subList(Math.max(0, log.size() - n), log.size()));
    }

    private synchronized void append(long seq) {
        log.add(seq);
    }

    @Test
    void itPollsOnlyWhileAStreamIsOpenAndSendsEachEntryOnce() throws Exception {
        for (long i = 1; i <= 5; i++) {
            append(i);
        }
        try (LiveFeed<Long> feed = new LiveFeed<>("test", this::recent, Long::longValue, e -> "id: " + e)) {
            assertFalse(feed.polling(), "nobody listens: no poller wakes up");
            LiveFeed.Subscriber s = feed.subscribe(3); // a browser reconnecting after entry 3
            assertTrue(feed.polling());
            append(6);
            append(7);
            List<String> got = new ArrayList<>();
            while (got.size() < 4) {
                String m = s.queue.poll(10, TimeUnit.SECONDS);
                if (m == null) {
                    break;
                }
                got.add(m);
            }
            assertEquals(List.of("id: 4", "id: 5", "id: 6", "id: 7"), got, "the gap, then what followed, once each");
            feed.unsubscribe(s);
            assertFalse(feed.polling(), "the last stream closed: the poller stops");

            LiveFeed.Subscriber fresh = feed.subscribe(-1); // only new entries
            append(8);
            assertEquals("id: 8", fresh.queue.poll(10, TimeUnit.SECONDS));
            assertEquals(0, fresh.queue.size());
        }
    }
}

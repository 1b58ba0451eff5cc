package org.tinysep.inactivity.internal.person;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.testing.AllocationMeter;

/**
 * Issue 29, item 1: in a home without a worn node (most homes) every room activity still asked whose it was,
 * building three sets, a list and a stream per activity on the radio's delivery thread (12 % of it at the
 * throughput limit). Without wearers a room activity now allocates nothing there; with one the rule is unchanged.
 */
class WearersCostTest {

    private static final Instant T0 = Instant.parse("2026-11-29T10:00:00Z");
    private static final DateTimeFormatter HH_MM = DateTimeFormatter.ofPattern("HH:mm").withZone(ZoneOffset.UTC);
    private final Wearers wearers = new Wearers(WearerSettings.defaults(), HH_MM::format);
    private final List<Wearers.Attribution> kept = new ArrayList<>(); // the answers escape, as they do in use

    @Test
    void roomActivityWithoutWearersAllocatesNothing() {
        double bytes = AllocationMeter.bytesPerCall(20_000, () -> {
            if (kept.size() > 1_000) {
                kept.clear();
            }
            kept.add(wearers.room(T0, "r-k", "Kitchen"));
        });
        assertTrue(bytes < 16, "bytes allocated per room activity without wearers: " + bytes);
        Wearers.Attribution a = wearers.room(T0, "r-k", "Kitchen");
        assertEquals(Set.of(), a.countsFor());
        assertEquals(Set.of(), a.seenThere());
        assertEquals(List.of(), a.notices());
    }
}
